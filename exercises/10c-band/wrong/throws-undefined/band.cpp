// Wrong on purpose: throws t2::Undefined for every input, the answer of a student who read
// only the "undefined" cases. It must score 0: every test that expects Undefined also checks
// an input where it must not be thrown (tests/test_exercises.cpp checks it for every exercise).
#include "band.hpp"

#include <t2/kernel/error.hpp>

namespace ex10c {

std::vector<long> owners(const std::vector<t2::Point>& P, const t2::Point& z) {
  (void)P;
  (void)z;
  throw t2::Undefined("owners(): undefined, whatever the input");
}

std::vector<long> band(const std::vector<t2::Point>& P) {
  (void)P;
  throw t2::Undefined("band(): undefined, whatever the input");
}

}  // namespace ex10c
