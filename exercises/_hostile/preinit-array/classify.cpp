// Hostile (issue 10): a function in .preinit_array runs before any constructor; it forges a
// verdict on every descriptor and exits 0 without implementing anything.
#include <unistd.h>
#include <stdexcept>
#include "classify.hpp"
namespace ex01 {
static void forge(int, char**, char**) {
  static const char kForged[] = "PASS\nR 1\n";
  for (int fd = 0; fd < 64; ++fd) { ssize_t n = write(fd, kForged, sizeof kForged - 1); (void)n; }
  _exit(0);
}
__attribute__((section(".preinit_array"), used)) static void (*preinit)(int, char**, char**) = forge;
static void attack() {}
Where where(const t2::Point&) { attack(); throw std::logic_error("where() is not implemented yet"); }
bool same_point(const t2::Point&, const t2::Point&) { attack(); throw std::logic_error("same_point() is not implemented yet"); }
bool antipodal(const t2::Point&, const t2::Point&) { attack(); throw std::logic_error("antipodal() is not implemented yet"); }
}  // namespace ex01
