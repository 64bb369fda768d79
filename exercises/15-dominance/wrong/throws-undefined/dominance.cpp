// Wrong on purpose: throws t2::Undefined for every input, the answer of a student who read
// only the "undefined" cases. It must score 0 (tests/test_exercises.cpp checks it).
#include "dominance.hpp"

#include <t2/kernel/error.hpp>

namespace ex15 {

long dominance(const std::vector<t2::Point>& P, const t2::Point& q, bool strict_x, bool strict_y) {
  (void)P, (void)q, (void)strict_x, (void)strict_y;
  throw t2::Undefined("dominance(): undefined, whatever the input");
}

long count(const std::vector<t2::Point>& P, const t2::Point& lo, const t2::Point& hi) {
  (void)P, (void)lo, (void)hi;
  throw t2::Undefined("count(): undefined, whatever the input");
}

}  // namespace ex15
