// Exercise 03 over the judge's wire (../harness/judge_wire.hpp), part of the grader, not of
// your solution. Compiled with T2_JUDGE_CHECKER it stands in for your functions inside the
// tests (each call goes to the sandboxed driver that runs your code); compiled without, it is the
// driver's table of your functions.
#include "mid.hpp"

#include "judge_wire.hpp"

#ifdef T2_JUDGE_CHECKER
namespace ex03 {
t2::ExactPoint midpoint(const t2::ExactPoint& p, const t2::ExactPoint& q) {
  return t2judge::call<t2::ExactPoint>("midpoint", p, q);
}
}  // namespace ex03
#else
const std::map<std::string, t2judge::Handler>& t2judge::table() {
  static const std::map<std::string, Handler> t = {
      {"midpoint", handler(&ex03::midpoint)},
  };
  return t;
}
#endif
