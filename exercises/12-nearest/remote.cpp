// Exercise 12 over the judge's wire (../harness/judge_wire.hpp), part of the grader, not of
// your solution. Compiled with T2_JUDGE_CHECKER it stands in for your functions inside the
// tests (each call goes to the sandboxed driver that runs your code); compiled without, it is the
// driver's table of your functions.
#include "nearest.hpp"

#include "judge_wire.hpp"

#ifdef T2_JUDGE_CHECKER
namespace ex12 {
std::vector<long> nearest_neighbours(const std::vector<t2::Point>& P, const std::vector<long>& E) {
  return t2judge::call<std::vector<long>>("nearest_neighbours", P, E);
}
}  // namespace ex12
#else
const std::map<std::string, t2judge::Handler>& t2judge::table() {
  static const std::map<std::string, Handler> t = {
      {"nearest_neighbours", handler(&ex12::nearest_neighbours)},
  };
  return t;
}
#endif
