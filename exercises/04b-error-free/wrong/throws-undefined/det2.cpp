// Wrong on purpose: throws t2::Undefined for every input, the answer of a student who read
// only the "undefined" cases. It must score 0: every test that expects Undefined also checks
// an input where it must not be thrown.
#include "det2.hpp"

#include <t2/kernel/error.hpp>

namespace ex04b {

t2::Sign det2_sign(double a, double b, double c, double d) {
  (void)a, (void)b, (void)c, (void)d;
  throw t2::Undefined("det2_sign(): undefined, whatever the input");
}

}  // namespace ex04b
