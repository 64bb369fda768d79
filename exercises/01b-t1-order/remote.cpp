// Exercise 01b over the judge's wire (../harness/judge_wire.hpp), part of the grader, not of
// your solution. Compiled with T2_JUDGE_CHECKER it stands in for your functions inside the
// tests (each call goes to the sandboxed driver that runs your code); compiled without, it is the
// driver's table of your functions.
#include "order.hpp"

#include "judge_wire.hpp"

#ifdef T2_JUDGE_CHECKER
namespace ex01b {
t2::Sign compare(double aw, double ax, double bw, double bx) {
  return t2judge::call<t2::Sign>("compare", aw, ax, bw, bx);
}
}  // namespace ex01b
#else
const std::map<std::string, t2judge::Handler>& t2judge::table() {
  static const std::map<std::string, Handler> t = {
      {"compare", handler(&ex01b::compare)},
  };
  return t;
}
#endif
