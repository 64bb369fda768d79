// Wrong on purpose: throws t2::Undefined for every input, the answer of a student who read
// only the "undefined" cases. It must score 0: no test of 07c expects Undefined (the
// preconditions hold in every test), so every test catches it.
#include "hull.hpp"

#include <t2/kernel/error.hpp>

namespace ex07c {

std::vector<long> hull(const std::vector<t2::Point>& P) {
  (void)P;
  throw t2::Undefined("hull(): undefined, whatever the input");
}

}  // namespace ex07c
