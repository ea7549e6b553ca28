#include "parser/zip_member.h"

#include <zip.h>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fmt/format.h>
#include <memory>

namespace darc {

namespace {

struct ZipCloser {
  void operator()(zip_t* z) const { zip_discard(z); }  // read only: nothing to write back
};
struct ZipFileCloser {
  void operator()(zip_file_t* f) const { zip_fclose(f); }
};

constexpr zip_uint64_t kReadChunkBytes = 1 << 20;

}  // namespace

std::optional<ZipMemberName> split_zip_member(const std::string& name) {
  std::string lower(name);
  std::transform(lower.begin(), lower.end(), lower.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  const size_t at = lower.find(".zip!");
  if (at == std::string::npos) return std::nullopt;
  return ZipMemberName{name.substr(0, at + 4), name.substr(at + 5)};
}

bool read_zip_member(const std::string& zip_path, const std::string& member, std::string& text, std::string& error,
                     const RibReadLimits& limits) {
  if (member.empty()) {
    error = "no member named after the '!'";
    return false;
  }
  if (member.size() >= 3 && member.compare(member.size() - 3, 3, ".gz") == 0) {
    error = "gzip-compressed members of a zip file are not supported";
    return false;
  }
  std::error_code ec;
  if (limits.regular_files_only && !std::filesystem::is_regular_file(zip_path, ec)) {
    error = "the zip is not a regular file";
    return false;
  }
  int code = 0;
  std::unique_ptr<zip_t, ZipCloser> archive(zip_open(zip_path.c_str(), ZIP_RDONLY, &code));
  if (!archive) {
    zip_error_t e;
    zip_error_init_with_code(&e, code);
    error = fmt::format("not a readable zip file ({})", zip_error_strerror(&e));
    zip_error_fini(&e);
    return false;
  }
  // Members are named as the zip stores them; a leading "./" or "/" in the RIB is not part of it.
  std::string name = member;
  while (name.rfind("./", 0) == 0) name.erase(0, 2);
  while (!name.empty() && name.front() == '/') name.erase(0, 1);
  const zip_int64_t index = zip_name_locate(archive.get(), name.c_str(), 0);
  if (index < 0) {
    error = "the zip file has no such member";
    return false;
  }
  zip_stat_t st;
  zip_stat_init(&st);
  if (zip_stat_index(archive.get(), zip_uint64_t(index), 0, &st) != 0 || !(st.valid & ZIP_STAT_SIZE)) {
    error = fmt::format("cannot read the member's size ({})", zip_strerror(archive.get()));
    return false;
  }
  if (limits.max_bytes > 0 && st.size > limits.max_bytes) {
    error = fmt::format("the member inflates to {} bytes, more than {}, the most a RIB text may be ({})", st.size,
                        limits.max_bytes, limits.max_bytes_source);
    return false;
  }
  std::unique_ptr<zip_file_t, ZipFileCloser> file(zip_fopen_index(archive.get(), zip_uint64_t(index), 0));
  if (!file) {
    error = fmt::format("cannot open the member ({})", zip_strerror(archive.get()));
    return false;
  }
  text.clear();
  text.reserve(size_t(st.size));
  std::string chunk(size_t(std::min<zip_uint64_t>(kReadChunkBytes, std::max<zip_uint64_t>(st.size, 1))), '\0');
  for (;;) {
    const zip_int64_t n = zip_fread(file.get(), chunk.data(), chunk.size());
    if (n < 0) {
      error = fmt::format("cannot read the member ({})", zip_file_strerror(file.get()));
      return false;
    }
    if (n == 0) break;
    // The stored size bounds what is read: a member that gives more than it says is refused.
    if (text.size() + size_t(n) > st.size) {
      error = "the member gives more bytes than the zip says it holds";
      return false;
    }
    text.append(chunk.data(), size_t(n));
  }
  return true;
}

}  // namespace darc
