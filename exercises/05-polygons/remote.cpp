// Exercise 05 over the judge's wire (../harness/judge_wire.hpp), part of the grader, not of
// your solution. Compiled with T2_JUDGE_CHECKER it stands in for your functions inside the
// tests (each call goes to the sandboxed driver that runs your code); compiled without, it is the
// driver's table of your functions.
#include "locate.hpp"

#include "judge_wire.hpp"

#ifdef T2_JUDGE_CHECKER
namespace ex05 {
t2::Sign locate(const std::vector<t2::Point>& P, const t2::Point& q) {
  return t2judge::call<t2::Sign>("locate", P, q);
}
}  // namespace ex05
#else
const std::map<std::string, t2judge::Handler>& t2judge::table() {
  static const std::map<std::string, Handler> t = {
      {"locate", handler(&ex05::locate)},
  };
  return t;
}
#endif
