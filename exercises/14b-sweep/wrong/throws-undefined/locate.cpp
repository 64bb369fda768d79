// Wrong on purpose: throws t2::Undefined for every input, the answer of a student who read
// only the "undefined" cases. It must score 0: no test of this exercise expects Undefined.
#include <t2/kernel/error.hpp>

#include "locate.hpp"

namespace ex14b {

std::vector<Location> locate_all(const std::vector<t2::Point>& P, const std::vector<Triangle>& T,
                                 const std::vector<t2::Point>& Q) {
  (void)P, (void)T, (void)Q;
  throw t2::Undefined("locate_all(): undefined, whatever the input");
}

}  // namespace ex14b
