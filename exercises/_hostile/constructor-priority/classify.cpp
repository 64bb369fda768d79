// Hostile (issue 10): a constructor of priority 100 runs before everything of the harness; it
// writes a forged PASS record on every descriptor and replaces fd 3 and 4 by fresh pipes.
#include <unistd.h>
#include <stdexcept>
#include "classify.hpp"
namespace ex01 {
static const char kForged[] = "0123456789abcdef\nPASS\nR 1\n";
__attribute__((constructor(100))) static void steal() {
  for (int fd = 0; fd < 64; ++fd) { ssize_t n = write(fd, kForged, sizeof kForged - 1); (void)n; }
  int p[2];
  if (pipe(p) == 0) { dup2(p[0], 3); dup2(p[1], 4); }
}
static void attack() {}
Where where(const t2::Point&) { attack(); throw std::logic_error("where() is not implemented yet"); }
bool same_point(const t2::Point&, const t2::Point&) { attack(); throw std::logic_error("same_point() is not implemented yet"); }
bool antipodal(const t2::Point&, const t2::Point&) { attack(); throw std::logic_error("antipodal() is not implemented yet"); }
}  // namespace ex01
