// Wrong on purpose: throws t2::Undefined for every input, the answer of a student who read
// only the "undefined" case. It must score 0: every test that expects Undefined also checks
// an input where it must not be thrown.
#include "insert.hpp"

#include <t2/kernel/error.hpp>

namespace ex09c {

std::vector<Kind> kinds(const std::vector<t2::Point>& P, const std::vector<long>& T) {
  (void)P;
  (void)T;
  throw t2::Undefined("kinds(): undefined, whatever the input");
}

std::vector<long> insert(const std::vector<t2::Point>& P, const std::vector<long>& T, long q) {
  (void)P;
  (void)T;
  (void)q;
  throw t2::Undefined("insert(): undefined, whatever the input");
}

}  // namespace ex09c
