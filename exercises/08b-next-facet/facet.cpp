// Exercise 08b: your solution. Replace the `throw` with your code, then run `t2 check 08b`.
#include "facet.hpp"

#include <stdexcept>

namespace ex08b {

std::vector<long> next_facet(const std::vector<t2::Point3>& P, const std::vector<long>& f, long k) {
  (void)P;
  (void)f;
  (void)k;
  throw std::logic_error("next_facet() is not implemented yet");
}

}  // namespace ex08b
