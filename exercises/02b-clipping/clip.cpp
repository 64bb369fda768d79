// Exercise 02b: your solution. Replace the `throw` with your code, then run `t2 check 02b`.
#include "clip.hpp"

#include <stdexcept>

namespace ex02b {

std::vector<t2::ExactPoint> clip(const t2::Point& p, const t2::Point& q, double W, double X, double Y) {
  (void)p, (void)q, (void)W, (void)X, (void)Y;
  throw std::logic_error("clip() is not implemented yet");
}

}  // namespace ex02b
