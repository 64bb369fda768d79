// Exercise 11 over the judge's wire (../harness/judge_wire.hpp), part of the grader, not of
// your solution. Compiled with T2_JUDGE_CHECKER it stands in for your functions inside the
// tests (each call goes to the sandboxed driver that runs your code); compiled without, it is the
// driver's table of your functions.
#include "vertex.hpp"

#include "judge_wire.hpp"

#ifdef T2_JUDGE_CHECKER
namespace ex11 {
t2::ExactPoint voronoi_vertex(const t2::Point& a, const t2::Point& b, const t2::Point& c) {
  return t2judge::call<t2::ExactPoint>("voronoi_vertex", a, b, c);
}
}  // namespace ex11
#else
const std::map<std::string, t2judge::Handler>& t2judge::table() {
  static const std::map<std::string, Handler> t = {
      {"voronoi_vertex", handler(&ex11::voronoi_vertex)},
  };
  return t;
}
#endif
