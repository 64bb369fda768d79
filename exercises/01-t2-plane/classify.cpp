// Exercise 01: your solution. Replace each `throw` with your code, then run `t2 check 01`.
#include "classify.hpp"

#include <stdexcept>

namespace ex01 {

Where where(const t2::Point& p) {
  (void)p;
  throw std::logic_error("where() is not implemented yet");
}

bool same_point(const t2::Point& p, const t2::Point& q) {
  (void)p;
  (void)q;
  throw std::logic_error("same_point() is not implemented yet");
}

bool antipodal(const t2::Point& p, const t2::Point& q) {
  (void)p;
  (void)q;
  throw std::logic_error("antipodal() is not implemented yet");
}

}  // namespace ex01
