// Exercise 10c over the judge's wire (../harness/judge_wire.hpp), part of the grader, not of
// your solution. Compiled with T2_JUDGE_CHECKER it stands in for your functions inside the
// tests (each call goes to the sandboxed driver that runs your code); compiled without, it is the
// driver's table of your functions.
#include "band.hpp"

#include "judge_wire.hpp"

#ifdef T2_JUDGE_CHECKER
namespace ex10c {
std::vector<long> owners(const std::vector<t2::Point>& P, const t2::Point& z) {
  return t2judge::call<std::vector<long>>("owners", P, z);
}
std::vector<long> band(const std::vector<t2::Point>& P) { return t2judge::call<std::vector<long>>("band", P); }
}  // namespace ex10c
#else
const std::map<std::string, t2judge::Handler>& t2judge::table() {
  static const std::map<std::string, Handler> t = {
      {"owners", handler(&ex10c::owners)},
      {"band", handler(&ex10c::band)},
  };
  return t;
}
#endif
