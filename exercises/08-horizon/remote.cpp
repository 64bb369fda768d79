// Exercise 08 over the judge's wire (../harness/judge_wire.hpp), part of the grader, not of
// your solution. Compiled with T2_JUDGE_CHECKER it stands in for your functions inside the
// tests (each call goes to the sandboxed driver that runs your code); compiled without, it is the
// driver's table of your functions.
#include "horizon.hpp"

#include "judge_wire.hpp"

#ifdef T2_JUDGE_CHECKER
namespace ex08 {
std::vector<long> insert_point(const std::vector<t2::Point3>& P, const std::vector<long>& H, long p) {
  return t2judge::call<std::vector<long>>("insert_point", P, H, p);
}
}  // namespace ex08
#else
const std::map<std::string, t2judge::Handler>& t2judge::table() {
  static const std::map<std::string, Handler> t = {
      {"insert_point", handler(&ex08::insert_point)},
  };
  return t;
}
#endif
