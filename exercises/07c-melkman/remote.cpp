// Exercise 07c over the judge's wire (../harness/judge_wire.hpp), part of the grader, not of
// your solution. Compiled with T2_JUDGE_CHECKER it stands in for your functions inside the
// tests (each call goes to the sandboxed driver that runs your code); compiled without, it is the
// driver's table of your functions.
#include "hull.hpp"

#include "judge_wire.hpp"

#ifdef T2_JUDGE_CHECKER
namespace ex07c {
std::vector<long> hull(const std::vector<t2::Point>& P) { return t2judge::call<std::vector<long>>("hull", P); }
}  // namespace ex07c
#else
const std::map<std::string, t2judge::Handler>& t2judge::table() {
  static const std::map<std::string, Handler> t = {
      {"hull", handler(&ex07c::hull)},
  };
  return t;
}
#endif
