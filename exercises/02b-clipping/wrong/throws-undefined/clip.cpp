// Wrong on purpose: throws t2::Undefined for every input, the answer of a student who read
// only the "undefined" cases. It must score 0: every test that expects Undefined also checks
// an input where it must not be thrown.
#include "clip.hpp"

#include <t2/kernel/error.hpp>

namespace ex02b {

std::vector<t2::ExactPoint> clip(const t2::Point& p, const t2::Point& q, double W, double X, double Y) {
  (void)p, (void)q, (void)W, (void)X, (void)Y;
  throw t2::Undefined("clip(): undefined, whatever the input");
}

}  // namespace ex02b
