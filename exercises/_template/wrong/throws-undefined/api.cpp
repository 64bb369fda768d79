// Wrong on purpose: throws t2::Undefined for every input, the answer of a student who read
// only the "undefined" cases. It must score 0: every test that expects Undefined also checks
// an input where it must not be thrown (tests/test_exercises.cpp checks it for every exercise).
#include "api.hpp"

#include <t2/kernel/error.hpp>

namespace exNN {

bool example(const t2::Point& p) {
  (void)p;
  throw t2::Undefined("example(): undefined, whatever the input");
}

}  // namespace exNN
