// Wrong on purpose: throws t2::Undefined for every input, the answer of a student who read
// only the "undefined" cases. It must score 0: every test that expects Undefined also checks
// an input where it must not be thrown.
#include "angles.hpp"

#include <t2/kernel/error.hpp>

namespace ex03b {

t2::Sign compare_angles(const t2::Point& a, const t2::Point& b, const t2::Point& c, const t2::Point& d,
                        const t2::Point& e, const t2::Point& f) {
  (void)a, (void)b, (void)c, (void)d, (void)e, (void)f;
  throw t2::Undefined("compare_angles(): undefined, whatever the input");
}

}  // namespace ex03b
