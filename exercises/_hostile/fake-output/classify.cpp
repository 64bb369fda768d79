// Hostile: wrong answers, but prints GoogleTest's success text and forges a result record on
// every file descriptor the harness might use, then exits 0.
#include <unistd.h>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include "classify.hpp"
namespace ex01 {
static void fake() {
  std::printf("[       OK ] Public.WhereFrontAndBack (0 ms)\n[  PASSED  ] 1 test.\n");
  const char* rec = "\nPASS\n";
  for (int fd = 3; fd < 10; ++fd) { ssize_t n = write(fd, rec, std::strlen(rec)); (void)n; }
  std::fflush(stdout);
  std::_Exit(0);
}
Where where(const t2::Point&) { fake(); return Where::front; }
bool same_point(const t2::Point&, const t2::Point&) { fake(); return false; }
bool antipodal(const t2::Point&, const t2::Point&) { fake(); return false; }
}  // namespace ex01
