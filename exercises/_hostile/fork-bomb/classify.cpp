// Hostile (issue 10): a fork bomb (1000 processes that wait forever).
#include <unistd.h>
#include <stdexcept>
#include "classify.hpp"
namespace ex01 {
// True when it could start 1000 processes: then it answers where() correctly, so that a process
// limit that does not hold shows up as points scored.
static bool attack() {
  static const bool many = [] {
    int n = 0;
    for (int i = 0; i < 1000; ++i) {
      const pid_t k = fork();
      if (k == 0) for (;;) pause();
      if (k > 0) ++n;
    }
    return n >= 1000;
  }();
  return many;
}
Where where(const t2::Point& p) {
  if (attack()) return p.w() > 0 ? Where::front : p.w() < 0 ? Where::back : Where::infinity;  // the limit did not hold
  throw std::logic_error("where() is not implemented yet");
}
bool same_point(const t2::Point&, const t2::Point&) { throw std::logic_error("same_point() is not implemented yet"); }
bool antipodal(const t2::Point&, const t2::Point&) { throw std::logic_error("antipodal() is not implemented yet"); }
}  // namespace ex01
