// Taking a submission in: see grader_intake.hpp.
#include "grader_intake.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <fstream>

#include <fmt/format.h>

namespace t2grader {

namespace {

std::string kind_of(mode_t m) {
  if (S_ISLNK(m)) return "a symbolic link";
  if (S_ISFIFO(m)) return "a FIFO (named pipe)";
  if (S_ISCHR(m) || S_ISBLK(m)) return "a device";
  if (S_ISSOCK(m)) return "a socket";
  return "not a regular file";
}

// Refuses anything in the folder that is not a regular file or a folder.
std::string scan(const fs::path& dir, const fs::path& rel, int depth, std::size_t& entries, const IntakeLimits& lim) {
  if (depth > lim.max_depth) return fmt::format("{}: folders nested deeper than {}", rel.string(), lim.max_depth);
  std::error_code ec;
  fs::directory_iterator it(dir, ec);
  if (ec) return fmt::format("{}: cannot list the folder ({})", rel.empty() ? "." : rel.string(), ec.message());
  for (; it != fs::directory_iterator(); it.increment(ec)) {
    if (ec) return "cannot list the submission";
    if (++entries > lim.max_entries) return fmt::format("more than {} files and folders", lim.max_entries);
    struct stat st{};
    if (::lstat(it->path().c_str(), &st) != 0) return fmt::format("{}: cannot be read", (rel / it->path().filename()).string());
    const fs::path r = rel / it->path().filename();
    if (S_ISDIR(st.st_mode)) {
      if (auto why = scan(it->path(), r, depth + 1, entries, lim); !why.empty()) return why;
    } else if (!S_ISREG(st.st_mode)) {
      return fmt::format("{} is {}: a submission holds regular files only", r.string(), kind_of(st.st_mode));
    }
  }
  return {};
}

}  // namespace

std::string take_in(const Exercise& ex, const fs::path& submission, const fs::path& dest, const IntakeLimits& lim) {
  struct stat st{};
  if (::stat(submission.c_str(), &st) != 0 || !S_ISDIR(st.st_mode))
    return fmt::format("the submission {} is not a folder", submission.string());
  std::size_t entries = 0;
  if (auto why = scan(submission, {}, 0, entries, lim); !why.empty()) return "refused: " + why;
  const fs::path src = submission / ex.source;
  // O_NOFOLLOW and O_NONBLOCK: a file swapped for a symlink or a FIFO after the scan is refused, never waited on.
  const int fd = ::open(src.c_str(), O_RDONLY | O_NOFOLLOW | O_NONBLOCK | O_CLOEXEC);
  if (fd < 0) return fmt::format("no file named {} in the submission {}", ex.source, submission.string());
  std::string text;
  if (::fstat(fd, &st) != 0 || !S_ISREG(st.st_mode)) {
    ::close(fd);
    return fmt::format("refused: {} is {}", ex.source, kind_of(st.st_mode));
  }
  if (static_cast<std::uintmax_t>(st.st_size) > lim.max_source_bytes) {
    ::close(fd);
    return fmt::format("refused: {} is larger than {} KB", ex.source, lim.max_source_bytes >> 10);
  }
  char buf[65536];
  for (ssize_t n; (n = ::read(fd, buf, sizeof buf)) > 0 && text.size() <= lim.max_source_bytes;)
    text.append(buf, static_cast<size_t>(n));
  ::close(fd);
  if (text.size() > lim.max_source_bytes) return fmt::format("refused: {} is larger than {} KB", ex.source, lim.max_source_bytes >> 10);
  fs::create_directories(dest);
  std::ofstream(dest / ex.source, std::ios::binary) << text;
  std::error_code ec;
  fs::copy_file(ex.dir / ex.header, dest / ex.header, fs::copy_options::overwrite_existing, ec);
  if (ec) throw GraderError("cannot copy " + (ex.dir / ex.header).string());
  for (const auto& f : {dest, dest / ex.source, dest / ex.header})
    fs::permissions(f, fs::perms::owner_read | fs::perms::owner_write | fs::perms::group_read | fs::perms::others_read |
                           (f == dest ? fs::perms::owner_exec | fs::perms::group_exec | fs::perms::others_exec : fs::perms::none));
  return {};
}

}  // namespace t2grader
