// Wrong on purpose: throws t2::Undefined for every input, the answer of a student who read
// only the "undefined" cases. It must score 0: every test that expects Undefined also checks
// an input where it must not be thrown.
#include "locate.hpp"

#include <t2/kernel/error.hpp>

namespace ex05 {

t2::Sign locate(const std::vector<t2::Point>& P, const t2::Point& q) {
  (void)P;
  (void)q;
  throw t2::Undefined("locate(): undefined, whatever the input");
}

}  // namespace ex05
