// Wrong on purpose: throws t2::Undefined for every input, the answer of a student who read
// only the "undefined" cases. It must score 0 (tests/test_exercises.cpp checks it).
#include "meeting.hpp"

#include <t2/kernel/error.hpp>

namespace ex13b {

std::vector<long> meeting_pair(const std::vector<t2::Point>& a, const std::vector<t2::Point>& b) {
  (void)a, (void)b;
  throw t2::Undefined("meeting_pair(): undefined, whatever the input");
}

}  // namespace ex13b
