// Hostile (issue 29, break 7): store 256 MB in /dev/shm, the tmpfs that bubblewrap mounts at /dev
// and that neither the /tmp size nor (without root) any cgroup bounds.
#include <cstdio>
#include <stdexcept>
#include <vector>
#include "classify.hpp"
namespace ex01 {
// True when /dev took 256 MB: then it answers where() correctly, so that a writable /dev shows
// up as points scored.
static bool attack() {
  static const bool filled = [] {
    std::vector<char> mb(1 << 20, 7);
    int written = 0;
    for (const char* path : {"/dev/shm/fill", "/dev/fill"}) {
      if (FILE* f = std::fopen(path, "w")) {
        for (written = 0; written < 256; ++written)
          if (std::fwrite(mb.data(), 1, mb.size(), f) != mb.size()) break;
        if (std::fclose(f) != 0) written = 0;
        if (written == 256) return true;
      }
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
