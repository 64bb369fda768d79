// The segment intersections of chapter 13 (t2/intersect/intersections.hpp), one registration
// each: timed by `t2 bench` on `t2 gen segments` (n segments with exactly n crossings); not yet
// animated.
#include "algorithms/registry.hpp"
#include "t2/intersect/intersections.hpp"

namespace t2cli::algorithms {
namespace {

T2_PROBLEM({"intersect", "points", Input::segments});

// The number of intersection points `a` reports on the segments of `in`.
Timed timed(BenchInput& in, t2::IntersectAlgorithm a) {
  return [&S = in.segments, a] { return t2::intersections(S, a).size(); };
}

T2_ALGORITHM({.name = "intersect",  // what `t2 intersect` runs
              .problem = "intersect",
              .summary = "t2::intersections, Bentley-Ottmann's sweep (front segments), O((n + k) log n)",
              .title = "Bentley-Ottmann sweep",
              .time = [](BenchInput& in) { return timed(in, t2::IntersectAlgorithm::sweep); },
              .peers = {"intersect-brute", "intersect-circular", "cgal"}});

T2_ALGORITHM({.name = "intersect-brute",
              .problem = "intersect",
              .summary = "t2::intersections by brute force, every pair, O(n^2), on the whole of T2",
              .title = "every pair of segments",
              .time = [](BenchInput& in) { return timed(in, t2::IntersectAlgorithm::brute); }});

T2_ALGORITHM({.name = "intersect-circular",  // t2 intersect --algorithm circular
              .problem = "intersect",
              .summary = "t2::intersections by the circular sweep of T2 (seed 000, Algorithm 16), O((n + k) log n), "
                         "every segment of T2",
              .title = "circular sweep of T2",
              .time = [](BenchInput& in) { return timed(in, t2::IntersectAlgorithm::circular); }});

}  // namespace
}  // namespace t2cli::algorithms
