// Hostile (issue 29, break 7): store 256 MB in /dev/shm, the tmpfs that bubblewrap mounts at /dev
// and that neither the /tmp size nor (without root) any cgroup bounds.
#include <cstdio>
#include <stdexcept>
#include <string>
#include <vector>
#include "classify.hpp"
namespace ex01 {
// True when /dev took 256 MB: then it answers where() correctly, so that a writable /dev shows
// up as points scored.
// Files of 8 MB each, under the limit on one file's size (RLIMIT_FSIZE, 16 MB).
static bool attack() {
  static const bool filled = [] {
    std::vector<char> mb(1 << 20, 7);
    for (const char* dir : {"/dev/shm/", "/dev/"}) {
      int written = 0;
      for (int file = 0; file < 32; ++file) {
        FILE* f = std::fopen((std::string(dir) + "fill" + std::to_string(file)).c_str(), "w");
        if (!f) break;
        for (int k = 0; k < 8 && std::fwrite(mb.data(), 1, mb.size(), f) == mb.size(); ++k) ++written;
        if (std::fclose(f) != 0) break;
      }
      if (written == 256) return true;
    }
    return false;
  }();
  return filled;
}
Where where(const t2::Point& p) {
  if (attack()) return p.w() > 0 ? Where::front : p.w() < 0 ? Where::back : Where::infinity;  // /dev was writable
  throw std::logic_error("where() is not implemented yet");
}
bool same_point(const t2::Point&, const t2::Point&) { throw std::logic_error("same_point() is not implemented yet"); }
bool antipodal(const t2::Point&, const t2::Point&) { throw std::logic_error("antipodal() is not implemented yet"); }
}  // namespace ex01
