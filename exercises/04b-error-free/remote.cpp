// Exercise 04b over the judge's wire (../harness/judge_wire.hpp), part of the grader, not of
// your solution. Compiled with T2_JUDGE_CHECKER it stands in for your functions inside the
// tests (each call goes to the sandboxed driver that runs your code); compiled without, it is the
// driver's table of your functions.
#include "det2.hpp"

#include "judge_wire.hpp"

#ifdef T2_JUDGE_CHECKER
namespace ex04b {
t2::Sign det2_sign(double a, double b, double c, double d) {
  return t2judge::call<t2::Sign>("det2_sign", a, b, c, d);
}
}  // namespace ex04b
#else
const std::map<std::string, t2judge::Handler>& t2judge::table() {
  static const std::map<std::string, Handler> t = {
      {"det2_sign", handler(&ex04b::det2_sign)},
  };
  return t;
}
#endif
