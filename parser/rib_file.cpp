#include "parser/rib_file.h"

#include <fcntl.h>
#include <fmt/format.h>
#include <sys/stat.h>
#include <unistd.h>
#include <zlib.h>

#include <algorithm>
#include <cerrno>
#include <cstring>

namespace darc {

namespace {

// Bytes asked of read() or gzread() at a time: few calls for a large file, little memory.
constexpr unsigned kReadChunkBytes = 1u << 16;

// Closes a file descriptor at scope end unless it was handed on.
class FileDescriptor {
 public:
  explicit FileDescriptor(int fd) : fd_(fd) {}
  ~FileDescriptor() {
    if (fd_ >= 0) ::close(fd_);
  }
  FileDescriptor(const FileDescriptor&) = delete;
  FileDescriptor& operator=(const FileDescriptor&) = delete;
  int get() const { return fd_; }
  int release() {
    const int fd = fd_;
    fd_ = -1;
    return fd;
  }

 private:
  int fd_;
};

const char* file_kind(mode_t mode) {
  if (S_ISCHR(mode)) return "a character device";
  if (S_ISBLK(mode)) return "a block device";
  if (S_ISFIFO(mode)) return "a named pipe";
  if (S_ISSOCK(mode)) return "a socket";
  return "a special file";
}

std::string size_text(std::uint64_t bytes) {
  if (bytes >= (std::uint64_t(1) << 30) && bytes % (std::uint64_t(1) << 30) == 0)
    return fmt::format("{} GiB", bytes >> 30);
  if (bytes >= (std::uint64_t(1) << 20)) return fmt::format("{:.0f} MiB", double(bytes) / double(1 << 20));
  return fmt::format("{} bytes", bytes);
}

std::string over_limit(const RibReadLimits& limits, bool gzipped) {
  return fmt::format("{} more than {}, the most a RIB text may be ({})", gzipped ? "decompresses to" : "holds",
                     size_text(limits.max_bytes),
                     limits.max_bytes_source.empty() ? "the limit" : limits.max_bytes_source);
}

// Appends `n` bytes unless the text would pass the limit. The buffer grows by doubling, but never
// past the limit, so that a text refused at the limit has not taken twice the limit first.
bool append_within(std::string& text, const char* bytes, size_t n, const RibReadLimits& limits) {
  const std::uint64_t needed = std::uint64_t(text.size()) + n;
  if (limits.max_bytes > 0 && needed > limits.max_bytes) return false;
  if (needed > text.capacity()) {
    std::uint64_t grown = std::max<std::uint64_t>(needed, 2 * std::uint64_t(text.capacity()));
    if (limits.max_bytes > 0) grown = std::min(grown, limits.max_bytes);
    text.reserve(static_cast<size_t>(grown));
  }
  text.append(bytes, n);
  return true;
}

bool read_plain(int fd, const struct stat& status, std::string& text, std::string& error,
                const RibReadLimits& limits) {
  const bool regular = S_ISREG(status.st_mode);
  const std::uint64_t size = regular ? std::uint64_t(status.st_size) : 0;
  if (regular && limits.max_bytes > 0 && size > limits.max_bytes) {
    error = over_limit(limits, false);
    return false;
  }
  // A regular file's size is known: one buffer of that size, since a growing buffer would hold up
  // to twice the text for a moment (the text is the largest thing a big scene's parse holds
  // besides its geometry).
  if (size > 0) text.reserve(static_cast<size_t>(size) + 1);
  std::string chunk(kReadChunkBytes, '\0');
  while (true) {
    const ssize_t n = ::read(fd, chunk.data(), chunk.size());
    if (n == 0) return true;
    if (n < 0) {
      if (errno == EINTR) continue;
      error = fmt::format("read error: {}", std::strerror(errno));
      return false;
    }
    if (!append_within(text, chunk.data(), static_cast<size_t>(n), limits)) {
      error = over_limit(limits, false);
      return false;
    }
    // An archive holds what its size says. More is a file that is not a plain file on a disk
    // (the kernel's files in /proc and /sys say 0 bytes and may never end) or one being written.
    if (limits.regular_files_only && text.size() > size) {
      error = fmt::format("gives more than the {} bytes its size says (a file of /proc or /sys, or one being "
                          "written): archives must be plain files",
                          size);
      return false;
    }
  }
}

bool read_gzip(FileDescriptor& fd, std::string& text, std::string& error, const RibReadLimits& limits) {
  gzFile file = gzdopen(fd.get(), "rb");
  if (!file) {
    error = "gzip: cannot read";
    return false;
  }
  fd.release();  // gzclose closes it
  std::string chunk(kReadChunkBytes, '\0');
  int n = 0;
  bool within = true;
  while ((n = gzread(file, chunk.data(), kReadChunkBytes)) > 0) {
    if (!append_within(text, chunk.data(), static_cast<size_t>(n), limits)) {
      within = false;
      break;
    }
  }
  int code = Z_OK;
  const char* message = gzerror(file, &code);
  bool ok = within && n == 0 && (code == Z_OK || code == Z_STREAM_END);
  if (!within) error = over_limit(limits, true);
  else if (!ok) error = std::string("gzip: ") + (message ? message : "read error");
  gzclose(file);
  return ok;
}

}  // namespace

bool read_rib_text(const std::string& path, std::string& text, std::string& error, const RibReadLimits& limits) {
  text.clear();
  const bool from_stdin = path == "-";
  // O_NONBLOCK: opening a named pipe must not wait for a writer when only regular files are
  // wanted (the pipe is refused below, after fstat).
  const int flags = O_RDONLY | O_CLOEXEC | O_NOCTTY | (limits.regular_files_only ? O_NONBLOCK : 0);
  FileDescriptor fd(from_stdin ? ::dup(STDIN_FILENO) : ::open(path.c_str(), flags));
  if (fd.get() < 0) {
    error = std::strerror(errno);
    return false;
  }
  struct stat status {};
  if (::fstat(fd.get(), &status) != 0) {
    error = std::strerror(errno);
    return false;
  }
  if (S_ISDIR(status.st_mode)) {
    error = "is a directory";
    return false;
  }
  if (limits.regular_files_only && !S_ISREG(status.st_mode)) {
    error = fmt::format("{}, not a regular file: archives must be regular files", file_kind(status.st_mode));
    return false;
  }
  if (limits.regular_files_only) ::fcntl(fd.get(), F_SETFL, ::fcntl(fd.get(), F_GETFL) & ~O_NONBLOCK);
  const bool gzipped = !from_stdin && path.size() >= 3 && path.compare(path.size() - 3, 3, ".gz") == 0;
  return gzipped ? read_gzip(fd, text, error, limits) : read_plain(fd.get(), status, text, error, limits);
}

}  // namespace darc
