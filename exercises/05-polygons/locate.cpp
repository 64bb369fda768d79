// Exercise 05: your solution. Replace the `throw` with your code, then run `t2 check 05`.
#include "locate.hpp"

#include <stdexcept>

namespace ex05 {

t2::Sign locate(const std::vector<t2::Point>& P, const t2::Point& q) {
  (void)P;
  (void)q;
  throw std::logic_error("locate() is not implemented yet");
}

}  // namespace ex05
