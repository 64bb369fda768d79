// Wrong on purpose: throws t2::Undefined for every input, the answer of a student who read
// only the "undefined" cases. It must score 0: every test that expects Undefined also checks
// an input where it must not be thrown.
#include "tree.hpp"

#include <t2/kernel/error.hpp>

namespace ex12b {

std::vector<long> spanning_tree(const std::vector<t2::Point>& P, const std::vector<long>& E) {
  (void)P;
  (void)E;
  throw t2::Undefined("spanning_tree(): undefined, whatever the input");
}

}  // namespace ex12b
