// Wrong on purpose: throws t2::Undefined for every input, the answer of a student who read
// only the "undefined" cases. It must score 0: every test that expects Undefined also checks
// an input where it must not be thrown.
#include "mid.hpp"

#include <t2/kernel/error.hpp>

namespace ex03 {

t2::ExactPoint midpoint(const t2::ExactPoint& p, const t2::ExactPoint& q) {
  (void)p;
  (void)q;
  throw t2::Undefined("midpoint(): undefined, whatever the input");
}

}  // namespace ex03
