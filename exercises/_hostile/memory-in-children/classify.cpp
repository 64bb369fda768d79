// Hostile (issue 10): six children of 400 MB each (the per-process limit is 512 MB).
#include <sys/wait.h>
#include <unistd.h>
#include <cstdlib>
#include <cstring>
#include <stdexcept>
#include "classify.hpp"
namespace ex01 {
static void attack() {
  for (int i = 0; i < 6; ++i)
    if (fork() == 0) {
      char* p = static_cast<char*>(std::malloc(400u << 20));
      if (p) std::memset(p, 1, 400u << 20);
      sleep(30);
      _exit(0);
    }
}
Where where(const t2::Point&) { attack(); throw std::logic_error("where() is not implemented yet"); }
bool same_point(const t2::Point&, const t2::Point&) { attack(); throw std::logic_error("same_point() is not implemented yet"); }
bool antipodal(const t2::Point&, const t2::Point&) { attack(); throw std::logic_error("antipodal() is not implemented yet"); }
}  // namespace ex01
