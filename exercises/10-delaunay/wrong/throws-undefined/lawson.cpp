// Wrong on purpose: throws t2::Undefined for every input, the answer of a student who read
// only the "undefined" cases. It must score 0: every test that expects Undefined also checks
// an input where it must not be thrown.
#include "lawson.hpp"

#include <t2/kernel/error.hpp>

namespace ex10 {

std::vector<long> delaunay_flips(const std::vector<t2::Point>& P, const std::vector<long>& T) {
  (void)P;
  (void)T;
  throw t2::Undefined("delaunay_flips(): undefined, whatever the input");
}

}  // namespace ex10
