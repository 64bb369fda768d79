// Wrong on purpose: throws t2::Undefined for every input, the answer of a student who read
// only the "undefined" cases. It must score 0 (tests/test_exercises.cpp checks it).
#include "locus.hpp"

#include <t2/kernel/error.hpp>

namespace ex15b {

std::vector<long> count(const std::vector<t2::Point>& P, const std::vector<t2::IsoRect>& R) {
  (void)P, (void)R;
  throw t2::Undefined("count(): undefined, whatever the input");
}

}  // namespace ex15b
