// Hostile (issue 10): fill /tmp (RAM-backed) with 1.5 GB.
#include <cstdio>
#include <vector>
#include <stdexcept>
#include "classify.hpp"
namespace ex01 {
// True when /tmp took 1.5 GB: then it answers where() correctly, so that an unbounded /tmp shows
// up as points scored.
static bool attack() {
  static const bool filled = [] {
    std::vector<char> mb(1 << 20, 7);
    int written = 0;
    if (FILE* f = std::fopen("/tmp/fill", "w")) {
      for (; written < 1536; ++written)
        if (std::fwrite(mb.data(), 1, mb.size(), f) != mb.size()) break;
      if (std::fclose(f) != 0) written = 0;
    }
    return written == 1536;
  }();
  return filled;
}
Where where(const t2::Point& p) {
  if (attack()) return p.w() > 0 ? Where::front : p.w() < 0 ? Where::back : Where::infinity;  // the limit did not hold
  throw std::logic_error("where() is not implemented yet");
}
bool same_point(const t2::Point&, const t2::Point&) { throw std::logic_error("same_point() is not implemented yet"); }
bool antipodal(const t2::Point&, const t2::Point&) { throw std::logic_error("antipodal() is not implemented yet"); }
}  // namespace ex01
