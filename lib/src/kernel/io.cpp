#include "t2/kernel/io.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <memory>
#include <string>
#include <system_error>

namespace t2 {

namespace fs = std::filesystem;

namespace {
[[noreturn]] void fail(const std::string& what) {
  throw std::system_error(errno, std::generic_category(), what);
}
}  // namespace

std::string read_file(const fs::path& path) {
  std::unique_ptr<std::FILE, int (*)(std::FILE*)> f(std::fopen(path.c_str(), "rb"), &std::fclose);
  if (!f) fail("cannot read " + path.string());
  std::string text;
  char buf[1 << 16];
  std::size_t n;
  while ((n = std::fread(buf, 1, sizeof buf, f.get())) > 0) text.append(buf, n);
  if (std::ferror(f.get())) fail("cannot read " + path.string());
  return text;
}

void write_file_atomically(const fs::path& path, std::string_view content) {
  const fs::path dir = path.has_parent_path() ? path.parent_path() : fs::path(".");
  fs::create_directories(dir);
  // Appended piece by piece: GCC 12 warns falsely (-Wrestrict) on "." + name + suffix.
  std::string tmpl = dir.string();
  tmpl += "/.";
  tmpl += path.filename().string();
  tmpl += ".XXXXXX";
  const int fd = ::mkstemp(tmpl.data());
  if (fd < 0) fail("cannot create a temporary file beside " + path.string());
  const char* p = content.data();
  std::size_t left = content.size();
  while (left > 0) {
    const ssize_t n = ::write(fd, p, left);
    if (n < 0) {
      if (errno == EINTR) continue;
      const int saved = errno;
      ::close(fd);
      ::unlink(tmpl.c_str());
      errno = saved;
      fail("cannot write " + path.string());
    }
    p += n;
    left -= static_cast<std::size_t>(n);
  }
  if (::fchmod(fd, 0644) != 0 || ::fsync(fd) != 0 || ::close(fd) != 0) {
    ::unlink(tmpl.c_str());
    fail("cannot write " + path.string());
  }
  if (::rename(tmpl.c_str(), path.c_str()) != 0) {
    const int saved = errno;
    ::unlink(tmpl.c_str());
    errno = saved;
    fail("cannot replace " + path.string());
  }
}

bool update_file_atomically(const fs::path& path, std::string_view content) {
  std::error_code ec;
  if (fs::is_regular_file(path, ec)) {
    try {
      if (read_file(path) == content) return false;
    } catch (const std::system_error&) {  // unreadable: rewrite it
    }
  }
  write_file_atomically(path, content);
  return true;
}

std::string trim(std::string_view text) {
  constexpr std::string_view space = " \t\r\n";
  const auto b = text.find_first_not_of(space);
  if (b == std::string_view::npos) return "";
  return std::string(text.substr(b, text.find_last_not_of(space) - b + 1));
}

}  // namespace t2
