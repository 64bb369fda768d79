// Exercise 03b: your solution. Replace the `throw` with your code, then run `t2 check 03b`.
#include "angles.hpp"

#include <stdexcept>

namespace ex03b {

t2::Sign compare_angles(const t2::Point& a, const t2::Point& b, const t2::Point& c, const t2::Point& d,
                        const t2::Point& e, const t2::Point& f) {
  (void)a, (void)b, (void)c, (void)d, (void)e, (void)f;
  throw std::logic_error("compare_angles() is not implemented yet");
}

}  // namespace ex03b
