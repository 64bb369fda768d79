// Exercise 13b over the judge's wire (../harness/judge_wire.hpp), part of the grader, not of
// your solution. Compiled with T2_JUDGE_CHECKER it stands in for your functions inside the
// tests (each call goes to the sandboxed driver that runs your code); compiled without, it is the
// driver's table of your functions.
#include "meeting.hpp"

#include "judge_wire.hpp"

#ifdef T2_JUDGE_CHECKER
namespace ex13b {
std::vector<long> meeting_pair(const std::vector<t2::Point>& a, const std::vector<t2::Point>& b) {
  return t2judge::call<std::vector<long>>("meeting_pair", a, b);
}
}  // namespace ex13b
#else
const std::map<std::string, t2judge::Handler>& t2judge::table() {
  static const std::map<std::string, Handler> t = {
      {"meeting_pair", handler(&ex13b::meeting_pair)},
  };
  return t;
}
#endif
