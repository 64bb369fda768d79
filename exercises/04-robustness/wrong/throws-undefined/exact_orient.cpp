// Wrong on purpose: throws t2::Undefined for every input, the answer of a student who read
// only the "undefined" cases. It must score 0: every test that expects Undefined also checks
// an input where it must not be thrown.
#include "exact_orient.hpp"

#include <t2/kernel/error.hpp>

namespace ex04 {

t2::Sign orient_exact(const t2::Point& p, const t2::Point& q, const t2::Point& r) {
  (void)p;
  (void)q;
  (void)r;
  throw t2::Undefined("orient_exact(): undefined, whatever the input");
}

}  // namespace ex04
