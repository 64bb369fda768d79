// The proximity problems of T² (chapter 12, t2/proximity/), timed by `t2 bench` on points of
// the plane; not yet animated (Kruskal's animation is issue 25's later part). Each but `sec`
// builds the Delaunay triangulation of each side in its run, so `t2 bench emst delaunay`
// compares the whole cost with the triangulation's.
#include "algorithms/registry.hpp"
#include "t2/proximity/closest_pair.hpp"
#include "t2/proximity/enclosing_circle.hpp"
#include "t2/proximity/nearest_neighbors.hpp"
#include "t2/proximity/spanning_tree.hpp"

namespace t2cli::algorithms {
namespace {

T2_PROBLEM({"emst", "edges", Input::plane});
T2_PROBLEM({"ann", "sites", Input::plane});
T2_PROBLEM({"closest-pair", "pairs", Input::plane});
T2_PROBLEM({"sec", "support sites", Input::plane});

T2_ALGORITHM({.name = "emst",  // what `t2 emst` runs
              .problem = "emst",
              .summary = "t2::minimum_spanning_tree: Kruskal on the Delaunay edges of each side of T2 (Algorithm 12)",
              .title = "the minimum spanning tree of T2 (Kruskal on the Delaunay edges)",
              .time = [](BenchInput& in) -> Timed {
                return [&P = in.points] { return t2::minimum_spanning_tree(std::span<const t2::Point>(P)).size(); };
              }});

T2_ALGORITHM({.name = "ann",  // what `t2 ann` runs
              .problem = "ann",
              .summary = "t2::all_nearest_neighbors: each site's nearest among its Delaunay neighbours (Algorithm 14)",
              .title = "all nearest neighbours in T2 (the Delaunay neighbours)",
              .time = [](BenchInput& in) -> Timed {
                return [&P = in.points] { return t2::all_nearest_neighbors(std::span<const t2::Point>(P)).size(); };
              }});

T2_ALGORITHM({.name = "closest-pair",  // what `t2 closest-pair` runs (--algorithm delaunay)
              .problem = "closest-pair",
              .summary = "t2::closest_pair: the nearest of the Delaunay edges of each side of T2",
              .title = "the closest pair in T2 (the Delaunay edges)",
              .time = [](BenchInput& in) -> Timed {
                return [&P = in.points] {
                  t2::closest_pair(std::span<const t2::Point>(P));
                  return std::size_t(1);
                };
              }});

T2_ALGORITHM({.name = "sec",  // what `t2 sec` runs
              .problem = "sec",
              .summary = "t2::smallest_enclosing_circle: Welzl's randomized algorithm, expected O(n) exact predicates",
              .title = "the smallest enclosing circle (Welzl)",
              .time = [](BenchInput& in) -> Timed {
                return [&P = in.points] {
                  return t2::smallest_enclosing_circle(std::span<const t2::Point>(P)).support.size();
                };
              },
              .peers = {"cgal"}});

}  // namespace
}  // namespace t2cli::algorithms
