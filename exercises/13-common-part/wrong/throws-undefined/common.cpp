// Wrong on purpose: throws t2::Undefined for every input, the answer of a student who read
// only the "undefined" cases. It must score 0 (tests/test_exercises.cpp checks it).
#include "common.hpp"

#include <t2/kernel/error.hpp>

namespace ex13 {

std::vector<t2::ExactPoint> common(const t2::Point& a, const t2::Point& b, const t2::Point& c, const t2::Point& d) {
  (void)a, (void)b, (void)c, (void)d;
  throw t2::Undefined("common(): undefined, whatever the input");
}

}  // namespace ex13
