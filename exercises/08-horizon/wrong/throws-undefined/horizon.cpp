// Wrong on purpose: throws t2::Undefined for every input, the answer of a student who read
// only the "undefined" cases. It must score 0: every test that expects Undefined also checks
// an input where it must not be thrown.
#include "horizon.hpp"

#include <t2/kernel/error.hpp>

namespace ex08 {

std::vector<long> insert_point(const std::vector<t2::Point3>& P, const std::vector<long>& H, long p) {
  (void)P;
  (void)H;
  (void)p;
  throw t2::Undefined("insert_point(): undefined, whatever the input");
}

}  // namespace ex08
