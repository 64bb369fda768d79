// Exercise 04 over the judge's wire (../harness/judge_wire.hpp), part of the grader, not of
// your solution. Compiled with T2_JUDGE_CHECKER it stands in for your functions inside the
// tests (each call goes to the sandboxed driver that runs your code); compiled without, it is the
// driver's table of your functions.
#include "exact_orient.hpp"

#include "judge_wire.hpp"

#ifdef T2_JUDGE_CHECKER
namespace ex04 {
t2::Sign orient_exact(const t2::Point& p, const t2::Point& q, const t2::Point& r) {
  return t2judge::call<t2::Sign>("orient_exact", p, q, r);
}
}  // namespace ex04
#else
const std::map<std::string, t2judge::Handler>& t2judge::table() {
  static const std::map<std::string, Handler> t = {
      {"orient_exact", handler(&ex04::orient_exact)},
  };
  return t;
}
#endif
