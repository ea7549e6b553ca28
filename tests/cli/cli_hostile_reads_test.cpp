// End-to-end: the files a hostile RIB can make darc read. An archive that is not a regular file
// (/dev/zero, /dev/stdin, a named pipe, a directory, a file of /proc) is an error at its request,
// never a hang; no text, a .gz inflated included, may pass the memory limit (a gzip bomb stops
// there); a file that is not RIB is refused whole and nothing of it reaches standard error or the
// image's metadata, and what messages quote of a RIB is bounded; a named pipe given on the
// command line is read once, by the parser.
#include <fcntl.h>
#include <sys/stat.h>
#include <zlib.h>

#include <thread>

#include "support/darc_command.h"
#include "support/image_files.h"

namespace darc::test {
namespace {

constexpr int kExitOk = 0;
constexpr int kExitSceneError = 3;

std::string frame_reading(const std::string& archive) {
  return "Display \"out.exr\" \"file\" \"rgba\"\nFormat 32 24 1\nPixelSamples 1 1\n"
         "Projection \"perspective\" \"fov\" [40]\nTranslate 0 0 5\nWorldBegin\nReadArchive \"" +
         archive + "\"\nSphere 0.5 -0.5 0.5 360\nWorldEnd\n";
}

TEST(CliHostileReads, ArchivesThatAreNotRegularFilesAreLocatedErrors) {
  ScratchDir dir("special-archives");
  ASSERT_EQ(::mkfifo((dir / "pipe").c_str(), 0600), 0);
  fs::create_directories(dir / "folder");
  for (const std::string name : {"/dev/zero", "/dev/stdin", "pipe", "folder", "/proc/self/environ"}) {
    SCOPED_TRACE(name);
    write_file(dir / "scene.rib", frame_reading(name));
    fs::remove(dir / "out.exr");
    RunResult r = run_darc(dir.path(), "scene.rib");
    EXPECT_EQ(r.exit_code, kExitSceneError) << r.err;
    EXPECT_NE(r.err.find("scene.rib:7:1: error: ReadArchive: cannot open archive \"" + name + "\": "),
              std::string::npos)
        << r.err;
    // The frame is rendered from the rest, and records the error.
    const std::optional<OIIO::ImageSpec> header = read_image_header(dir / "out.exr");
    ASSERT_TRUE(header);
    EXPECT_EQ(header->get_int_attribute("darc:errors"), 1);
  }
}

// A password file named as an archive: one error, which quotes nothing of it, in the messages and
// in the image (darc:first_error).
TEST(CliHostileReads, AFileThatIsNotRibLeaksNothing) {
  ScratchDir dir("not-rib");
  write_file(dir / "passwd", "root:x:0:0:root:/root:/bin/bash\nalice:x:1000:1000::/home/alice:/bin/sh\n");
  write_file(dir / "scene.rib", frame_reading("passwd"));
  RunResult r = run_darc(dir.path(), "scene.rib");
  EXPECT_EQ(r.exit_code, kExitSceneError) << r.err;
  EXPECT_NE(r.err.find("scene.rib:7:1: error: ReadArchive: cannot read archive \"passwd\": it does not begin with a "
                       "RIB request"),
            std::string::npos)
      << r.err;
  const std::optional<OIIO::ImageSpec> header = read_image_header(dir / "out.exr");
  ASSERT_TRUE(header);
  const std::string first_error = header->get_string_attribute("darc:first_error");
  EXPECT_NE(first_error.find("cannot read archive"), std::string::npos) << first_error;
  for (const char* secret : {"root", "alice", "/bin/"}) {
    EXPECT_EQ(r.err.find(secret), std::string::npos) << r.err;
    EXPECT_EQ(first_error.find(secret), std::string::npos) << first_error;
  }
}

// A RIB whose error quotes a long value: the message and the image keep a short excerpt of it.
TEST(CliHostileReads, MessagesQuoteAShortExcerptOfTheRib) {
  ScratchDir dir("excerpt");
  const std::string value = "HEAD" + std::string(300, 'x') + "MIDDLE" + std::string(300, 'y') + "TAIL";
  write_file(dir / "part.rib", "Basis \"" + value + "\" 3 \"bezier\" 3\n");
  write_file(dir / "scene.rib", frame_reading("part.rib"));
  RunResult r = run_darc(dir.path(), "scene.rib");
  EXPECT_EQ(r.exit_code, kExitSceneError) << r.err;
  EXPECT_NE(r.err.find("part.rib:1:1: error: Basis: "), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("HEAD"), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find("MIDDLE"), std::string::npos) << r.err;
  const std::optional<OIIO::ImageSpec> header = read_image_header(dir / "out.exr");
  ASSERT_TRUE(header);
  const std::string first_error = header->get_string_attribute("darc:first_error");
  EXPECT_NE(first_error.find("HEAD"), std::string::npos) << first_error;
  EXPECT_EQ(first_error.find("MIDDLE"), std::string::npos) << first_error;
  EXPECT_LT(first_error.size(), 300u) << first_error;
}

// Writes `bytes` spaces as a gzip file (about 1 kB on disk per MiB of text).
void write_gzip_of_spaces(const fs::path& path, size_t bytes) {
  gzFile file = gzopen(path.c_str(), "wb9");
  ASSERT_NE(file, nullptr);
  const std::string block(1 << 16, ' ');
  for (size_t written = 0; written < bytes; written += block.size())
    ASSERT_EQ(gzwrite(file, block.data(), unsigned(block.size())), int(block.size()));
  gzclose(file);
}

// A gzip bomb: 96 MiB of text in a file of about 100 kB, under --memory-limit 64M (kept small
// so the test is quick; the default limit is what the machine allows).
TEST(CliHostileReads, AGzipBombStopsAtTheMemoryLimit) {
  ScratchDir dir("gzip-bomb");
  write_gzip_of_spaces(dir / "bomb.rib.gz", size_t(96) << 20);
  ASSERT_LT(fs::file_size(dir / "bomb.rib.gz"), 1u << 20);
  write_file(dir / "scene.rib", "ReadArchive \"bomb.rib.gz\"\nSides 1\n");
  RunResult r = run_darc(dir.path(), "--cat --memory-limit 64M scene.rib");
  EXPECT_EQ(r.exit_code, kExitSceneError) << r.err;
  EXPECT_NE(r.err.find("scene.rib:1:1: error: ReadArchive: cannot open archive \"bomb.rib.gz\": decompresses to "
                       "more than 64 MiB, the most a RIB text may be (the memory limit, from --memory-limit)"),
            std::string::npos)
      << r.err;
  EXPECT_NE(r.out.find("Sides 1"), std::string::npos) << "the requests after it are read";
  // The same file as the input itself.
  RunResult input = run_darc(dir.path(), "--cat --memory-limit 64M bomb.rib.gz");
  EXPECT_EQ(input.exit_code, kExitSceneError) << input.err;
  EXPECT_NE(input.err.find("error: cannot read \"bomb.rib.gz\": decompresses to more than 64 MiB"), std::string::npos)
      << input.err;
}

// A device on the command line is the user's choice, but it still ends: at the memory limit.
TEST(CliHostileReads, AnEndlessInputStopsAtTheMemoryLimit) {
  ScratchDir dir("endless");
  RunResult r = run_darc(dir.path(), "--cat --memory-limit 32M /dev/zero");
  EXPECT_EQ(r.exit_code, kExitSceneError) << r.err;
  EXPECT_NE(r.err.find("error: cannot read \"/dev/zero\": holds more than 32 MiB"), std::string::npos) << r.err;
}

// A named pipe on the command line (a generator writing into it) is read by the parser alone:
// counting the frames for the progress line must not open it.
TEST(CliHostileReads, ANamedPipeOnTheCommandLineIsReadOnce) {
  ScratchDir dir("pipe-input");
  ASSERT_EQ(::mkfifo((dir / "scene.pipe").c_str(), 0600), 0);
  const std::string scene = frame_reading("part.rib");
  write_file(dir / "part.rib", "Color 1 0 0\n");
  std::thread writer([&] {
    const int fd = ::open((dir / "scene.pipe").c_str(), O_WRONLY);  // waits for darc to open it
    if (fd < 0) return;
    ssize_t written = ::write(fd, scene.data(), scene.size());
    (void)written;
    ::close(fd);
  });
  RunOptions loud;
  loud.quiet = false;
  RunResult r = run_darc(dir.path(), "scene.pipe", loud);
  writer.join();
  EXPECT_EQ(r.exit_code, kExitOk) << r.err;
  EXPECT_TRUE(fs::exists(dir / "out.exr")) << r.err;
}

}  // namespace
}  // namespace darc::test
