// Exercise 08: your solution. Replace the `throw` with your code, then run `t2 check 08`.
#include "horizon.hpp"

#include <stdexcept>

namespace ex08 {

std::vector<long> insert_point(const std::vector<t2::Point3>& P, const std::vector<long>& H, long p) {
  (void)P;
  (void)H;
  (void)p;
  throw std::logic_error("insert_point() is not implemented yet");
}

}  // namespace ex08
