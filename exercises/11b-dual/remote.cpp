// Exercise 11b over the judge's wire (../harness/judge_wire.hpp), part of the grader, not of
// your solution. Compiled with T2_JUDGE_CHECKER it stands in for your functions inside the
// tests (each call goes to the sandboxed driver that runs your code); compiled without, it is the
// driver's table of your functions.
#include "dual.hpp"

#include "judge_wire.hpp"

#ifdef T2_JUDGE_CHECKER
namespace ex11b {
std::vector<t2::ExactPoint> voronoi_vertices(const std::vector<t2::Point>& P, const std::vector<long>& F) {
  return t2judge::call<std::vector<t2::ExactPoint>>("voronoi_vertices", P, F);
}
std::vector<long> voronoi_edges(const std::vector<t2::Point>& P, const std::vector<long>& F) {
  return t2judge::call<std::vector<long>>("voronoi_edges", P, F);
}
}  // namespace ex11b
#else
const std::map<std::string, t2judge::Handler>& t2judge::table() {
  static const std::map<std::string, Handler> t = {
      {"voronoi_vertices", handler(&ex11b::voronoi_vertices)},
      {"voronoi_edges", handler(&ex11b::voronoi_edges)},
  };
  return t;
}
#endif
