// Exercise 15: your solution. Replace the `throw`s with your code, then run `t2 check 15`.
#include "dominance.hpp"

#include <stdexcept>

namespace ex15 {

long dominance(const std::vector<t2::Point>& P, const t2::Point& q, bool strict_x, bool strict_y) {
  (void)P, (void)q, (void)strict_x, (void)strict_y;
  throw std::logic_error("dominance() is not implemented yet");
}

long count(const std::vector<t2::Point>& P, const t2::Point& lo, const t2::Point& hi) {
  (void)P, (void)lo, (void)hi;
  throw std::logic_error("count() is not implemented yet");
}

}  // namespace ex15
