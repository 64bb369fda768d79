// Exercise 06: your solution. Replace the `throw`s with your code, then run `t2 check 06`.
#include "hemisphere.hpp"

#include <stdexcept>

namespace ex06 {

t2::ExactPoint hemisphere(const std::vector<t2::Point>& P) {
  (void)P;
  throw std::logic_error("hemisphere() is not implemented yet");
}

std::vector<long> witness(const std::vector<t2::Point>& P) {
  (void)P;
  throw std::logic_error("witness() is not implemented yet");
}

}  // namespace ex06
