// Exercise 13 over the judge's wire (../harness/judge_wire.hpp), part of the grader, not of
// your solution. Compiled with T2_JUDGE_CHECKER it stands in for your functions inside the
// tests (each call goes to the sandboxed driver that runs your code); compiled without, it is the
// driver's table of your functions.
#include "common.hpp"

#include "judge_wire.hpp"

#ifdef T2_JUDGE_CHECKER
namespace ex13 {
std::vector<t2::ExactPoint> common(const t2::Point& a, const t2::Point& b, const t2::Point& c, const t2::Point& d) {
  return t2judge::call<std::vector<t2::ExactPoint>>("common", a, b, c, d);
}
}  // namespace ex13
#else
const std::map<std::string, t2judge::Handler>& t2judge::table() {
  static const std::map<std::string, Handler> t = {
      {"common", handler(&ex13::common)},
  };
  return t;
}
#endif
