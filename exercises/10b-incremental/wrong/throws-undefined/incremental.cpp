// Wrong on purpose: throws t2::Undefined for every input, the answer of a student who read
// only the "undefined" cases. It must score 0: every test that expects Undefined also checks
// an input where it must not be thrown.
#include "incremental.hpp"

#include <t2/kernel/error.hpp>

namespace ex10b {

std::vector<long> delaunay(const std::vector<t2::Point>& P) {
  (void)P;
  throw t2::Undefined("delaunay(): undefined, whatever the input");
}

}  // namespace ex10b
