// Wrong on purpose: throws t2::Undefined for every input, the answer of a student who read
// only the "undefined" cases. It must score 0: every test that expects Undefined also checks
// an input where it must not be thrown.
#include "facet.hpp"

#include <t2/kernel/error.hpp>

namespace ex08b {

std::vector<long> next_facet(const std::vector<t2::Point3>& P, const std::vector<long>& f, long k) {
  (void)P;
  (void)f;
  (void)k;
  throw t2::Undefined("next_facet(): undefined, whatever the input");
}

}  // namespace ex08b
