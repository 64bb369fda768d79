// The grader's cache: see grader_cache.hpp.
#include "grader_cache.hpp"

#include <sys/stat.h>
#include <unistd.h>

#include <fstream>
#include <random>
#include <sstream>

#include <fmt/format.h>

#include "grader_sandbox.hpp"
#include "process.hpp"

#ifndef T2_BINARY_DIR
#define T2_BINARY_DIR "./build"
#endif

namespace t2grader {

namespace {

// The cache folder, when it is ours and only ours to write; else the run's private folder.
fs::path cache_dir(const fs::path& work) {
  const fs::path c = fs::path(T2_BINARY_DIR) / "grader-cache";
  std::error_code ec;
  fs::create_directories(c, ec);
  struct stat st{};
  if (::lstat(c.c_str(), &st) == 0 && S_ISDIR(st.st_mode) && st.st_uid == ::geteuid() && !(st.st_mode & 022) &&
      ::access(c.c_str(), W_OK) == 0)
    return c;
  ::chmod(c.c_str(), 0755);
  if (::lstat(c.c_str(), &st) == 0 && S_ISDIR(st.st_mode) && st.st_uid == ::geteuid() && !(st.st_mode & 022)) return c;
  return work;
}

std::string random_tag() {
  std::random_device rd;
  return fmt::format("{:08x}", rd());
}

bool is_hex64(const std::string& s) {
  return s.size() == 64 && s.find_first_not_of("0123456789abcdef") == std::string::npos;
}

}  // namespace

std::string read_text(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

std::uint64_t fnv1a(const std::string& s, std::uint64_t h) {
  for (unsigned char c : s) {
    h ^= c;
    h *= 1099511628211ull;
  }
  return h;
}

std::string run_out(std::vector<std::string> argv) {
  t2proc::Spec s;
  s.argv = std::move(argv);
  s.err = t2proc::Stream::discard;
  s.limits.wall_seconds = 60;
  const auto r = t2proc::run(s);
  return r.ok() ? r.out : std::string();
}

std::string sha256(const fs::path& p) {
  // "HEX *FILE" from both commands.
  static const bool openssl = !run_out({"openssl", "version"}).empty();
  if (openssl)
    if (std::string h = run_out({"openssl", "dgst", "-sha256", "-r", p.string()}).substr(0, 64); is_hex64(h)) return h;
  std::string h = run_out({"sha256sum", "--", p.string()}).substr(0, 64);
  return is_hex64(h) ? h : std::string();
}

fs::path cached(const fs::path& work, const std::string& stem, std::uint64_t key,
                const std::function<void(const fs::path&)>& make) {
  const fs::path dir = cache_dir(work);
  const fs::path f = dir / fmt::format("{}-{:016x}", stem, key), sum = f.string() + ".sha256";
  std::error_code ec;
  if (fs::is_regular_file(f, ec) && fs::is_regular_file(sum, ec) && !fs::is_symlink(f, ec)) {
    const std::string want = read_text(sum), got = sha256(f);
    if (want.size() == 64 && got == want) return f;
  }
  const fs::path tmp = dir / fmt::format("{}.tmp{}-{}", f.filename().string(), ::getpid(), random_tag());
  make(tmp);
  const std::string got = sha256(tmp);
  if (got.size() != 64) throw GraderError("cannot hash " + tmp.string());
  const fs::path sum_tmp = tmp.string() + ".sha256";
  std::ofstream(sum_tmp) << got;
  fs::rename(tmp, f, ec);
  if (!ec) fs::rename(sum_tmp, sum, ec);
  if (ec) return tmp;
  return f;
}

}  // namespace t2grader
