// Exercise 15 over the judge's wire (../harness/judge_wire.hpp), part of the grader, not of
// your solution. Compiled with T2_JUDGE_CHECKER it stands in for your functions inside the
// tests (each call goes to the sandboxed driver that runs your code); compiled without, it is the
// driver's table of your functions.
#include "dominance.hpp"

#include "judge_wire.hpp"

#ifdef T2_JUDGE_CHECKER
namespace ex15 {
long dominance(const std::vector<t2::Point>& P, const t2::Point& q, bool strict_x, bool strict_y) {
  return t2judge::call<long>("dominance", P, q, strict_x, strict_y);
}
long count(const std::vector<t2::Point>& P, const t2::Point& lo, const t2::Point& hi) {
  return t2judge::call<long>("count", P, lo, hi);
}
}  // namespace ex15
#else
const std::map<std::string, t2judge::Handler>& t2judge::table() {
  static const std::map<std::string, Handler> t = {
      {"dominance", handler(&ex15::dominance)},
      {"count", handler(&ex15::count)},
  };
  return t;
}
#endif
