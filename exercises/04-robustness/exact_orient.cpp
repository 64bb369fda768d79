// Exercise 04: your solution. Replace the `throw` with your code, then run `t2 check 04`.
#include "exact_orient.hpp"

#include <stdexcept>

namespace ex04 {

t2::Sign orient_exact(const t2::Point& p, const t2::Point& q, const t2::Point& r) {
  (void)p;
  (void)q;
  (void)r;
  throw std::logic_error("orient_exact() is not implemented yet");
}

}  // namespace ex04
