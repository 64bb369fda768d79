// Exercise 10 over the judge's wire (../harness/judge_wire.hpp), part of the grader, not of
// your solution. Compiled with T2_JUDGE_CHECKER it stands in for your functions inside the
// tests (each call goes to the sandboxed driver that runs your code); compiled without, it is the
// driver's table of your functions.
#include "lawson.hpp"

#include "judge_wire.hpp"

#ifdef T2_JUDGE_CHECKER
namespace ex10 {
std::vector<long> delaunay_flips(const std::vector<t2::Point>& P, const std::vector<long>& T) {
  return t2judge::call<std::vector<long>>("delaunay_flips", P, T);
}
}  // namespace ex10
#else
const std::map<std::string, t2judge::Handler>& t2judge::table() {
  static const std::map<std::string, Handler> t = {
      {"delaunay_flips", handler(&ex10::delaunay_flips)},
  };
  return t;
}
#endif
