// Hostile (issue 10): as root in its namespace, remount /usr read-write and leave a file in /usr/local.
#include <sys/mount.h>
#include <cstdio>
#include <stdexcept>
#include "classify.hpp"
namespace ex01 {
static void attack() {
  mount("none", "/usr", nullptr, MS_REMOUNT | MS_BIND, nullptr);
  if (FILE* f = std::fopen("/usr/local/t2-escaped-remount", "w")) { std::fputs("escaped\n", f); std::fclose(f); }
}
Where where(const t2::Point&) { attack(); throw std::logic_error("where() is not implemented yet"); }
bool same_point(const t2::Point&, const t2::Point&) { attack(); throw std::logic_error("same_point() is not implemented yet"); }
bool antipodal(const t2::Point&, const t2::Point&) { attack(); throw std::logic_error("antipodal() is not implemented yet"); }
}  // namespace ex01
