// Exercise 02 over the judge's wire (../harness/judge_wire.hpp), part of the grader, not of
// your solution. Compiled with T2_JUDGE_CHECKER it stands in for your functions inside the
// tests (each call goes to the sandboxed driver that runs your code); compiled without, it is the
// driver's table of your functions.
#include "segments.hpp"

#include "judge_wire.hpp"

#ifdef T2_JUDGE_CHECKER
namespace ex02 {
Shape shape(const t2::Point& p, const t2::Point& q) { return t2judge::call<Shape>("shape", p, q); }
bool contains(const t2::Point& p, const t2::Point& q, const t2::Point& r) {
  return t2judge::call<bool>("contains", p, q, r);
}
}  // namespace ex02
#else
const std::map<std::string, t2judge::Handler>& t2judge::table() {
  static const std::map<std::string, Handler> t = {
      {"shape", handler(&ex02::shape)},
      {"contains", handler(&ex02::contains)},
  };
  return t;
}
#endif
