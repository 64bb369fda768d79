// Exercise 14b: your solution. Replace the `throw` with your code, then run `t2 check 14b`.
#include "locate.hpp"

#include <stdexcept>

namespace ex14b {

std::vector<Location> locate_all(const std::vector<t2::Point>& P, const std::vector<Triangle>& T,
                                 const std::vector<t2::Point>& Q) {
  (void)P, (void)T, (void)Q;
  throw std::logic_error("locate_all() is not implemented yet");
}

}  // namespace ex14b
