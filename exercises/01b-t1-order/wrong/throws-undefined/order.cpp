// Wrong on purpose: throws t2::Undefined for every input, the answer of a student who read
// only the "undefined" cases. It must score 0: every test that expects Undefined also checks
// an input where it must not be thrown.
#include "order.hpp"

#include <t2/kernel/error.hpp>

namespace ex01b {

t2::Sign compare(double aw, double ax, double bw, double bx) {
  (void)aw, (void)ax, (void)bw, (void)bx;
  throw t2::Undefined("compare(): undefined, whatever the input");
}

}  // namespace ex01b
