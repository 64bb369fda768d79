// Exercise 09c over the judge's wire (../harness/judge_wire.hpp), part of the grader, not of
// your solution. Compiled with T2_JUDGE_CHECKER it stands in for your functions inside the
// tests (each call goes to the sandboxed driver that runs your code); compiled without, it is the
// driver's table of your functions.
#include "insert.hpp"

#include "judge_wire.hpp"

#ifdef T2_JUDGE_CHECKER
namespace ex09c {
std::vector<Kind> kinds(const std::vector<t2::Point>& P, const std::vector<long>& T) {
  return t2judge::call<std::vector<Kind>>("kinds", P, T);
}
std::vector<long> insert(const std::vector<t2::Point>& P, const std::vector<long>& T, long q) {
  return t2judge::call<std::vector<long>>("insert", P, T, q);
}
}  // namespace ex09c
#else
const std::map<std::string, t2judge::Handler>& t2judge::table() {
  static const std::map<std::string, Handler> t = {
      {"kinds", handler(&ex09c::kinds)},
      {"insert", handler(&ex09c::insert)},
  };
  return t;
}
#endif
