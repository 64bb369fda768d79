// Wrong on purpose: throws t2::Undefined for every input, the answer of a student who read
// only the "undefined" cases. It must score 0: every test that expects Undefined also checks
// an input where it must not be thrown.
#include "crossing.hpp"

#include <t2/kernel/error.hpp>

namespace ex05b {

t2::ExactPoint crossing(const t2::Point& a, const t2::Point& b, const t2::Point& c, const t2::Point& d) {
  (void)a, (void)b, (void)c, (void)d;
  throw t2::Undefined("crossing(): undefined, whatever the input");
}

}  // namespace ex05b
