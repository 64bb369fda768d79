// Exercise 07: your solution. Replace the `throw` with your code, then run `t2 check 07`.
#include "width.hpp"

#include <stdexcept>

namespace ex07 {

std::vector<long> width(const std::vector<t2::Point>& P) {
  (void)P;
  throw std::logic_error("width() is not implemented yet");
}

}  // namespace ex07
