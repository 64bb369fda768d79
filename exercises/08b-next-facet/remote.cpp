// Exercise 08b over the judge's wire (../harness/judge_wire.hpp), part of the grader, not of
// your solution. Compiled with T2_JUDGE_CHECKER it stands in for your functions inside the
// tests (each call goes to the sandboxed driver that runs your code); compiled without, it is the
// driver's table of your functions.
#include "facet.hpp"

#include "judge_wire.hpp"

#ifdef T2_JUDGE_CHECKER
namespace ex08b {
std::vector<long> next_facet(const std::vector<t2::Point3>& P, const std::vector<long>& f, long k) {
  return t2judge::call<std::vector<long>>("next_facet", P, f, k);
}
}  // namespace ex08b
#else
const std::map<std::string, t2judge::Handler>& t2judge::table() {
  static const std::map<std::string, Handler> t = {
      {"next_facet", handler(&ex08b::next_facet)},
  };
  return t;
}
#endif
