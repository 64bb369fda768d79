// Exercise 01 over the judge's wire (../harness/judge_wire.hpp), part of the grader, not of
// your solution. Compiled with T2_JUDGE_CHECKER it stands in for your functions inside the
// tests (each call goes to the sandboxed driver that runs your code); compiled without, it is the
// driver's table of your functions.
#include "classify.hpp"

#include "judge_wire.hpp"

#ifdef T2_JUDGE_CHECKER
namespace ex01 {
Where where(const t2::Point& p) { return t2judge::call<Where>("where", p); }
bool same_point(const t2::Point& p, const t2::Point& q) { return t2judge::call<bool>("same_point", p, q); }
bool antipodal(const t2::Point& p, const t2::Point& q) { return t2judge::call<bool>("antipodal", p, q); }
}  // namespace ex01
#else
const std::map<std::string, t2judge::Handler>& t2judge::table() {
  static const std::map<std::string, Handler> t = {
      {"where", handler(&ex01::where)},
      {"same_point", handler(&ex01::same_point)},
      {"antipodal", handler(&ex01::antipodal)},
  };
  return t;
}
#endif
