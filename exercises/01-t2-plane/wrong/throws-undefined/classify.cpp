// Wrong on purpose: throws t2::Undefined for every input, the answer of a student who read
// only the "undefined" cases. It must score 0: every test that expects Undefined also checks
// an input where it must not be thrown.
#include "classify.hpp"

#include <t2/kernel/error.hpp>

namespace ex01 {

Where where(const t2::Point& p) {
  (void)p;
  throw t2::Undefined("where(): undefined, whatever the input");
}

bool same_point(const t2::Point& p, const t2::Point& q) {
  (void)p;
  (void)q;
  throw t2::Undefined("same_point(): undefined, whatever the input");
}

bool antipodal(const t2::Point& p, const t2::Point& q) {
  (void)p;
  (void)q;
  throw t2::Undefined("antipodal(): undefined, whatever the input");
}

}  // namespace ex01
