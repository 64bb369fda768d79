// The hulls in R³ of chapter 08 (t2/hull3d/convex_hull_3d.hpp), one registration each. Their
// input is not of T², so they have no scene and no animation: `t2 bench` times them.
#include <algorithm>
#include <cstdint>

#include "algorithms/registry.hpp"
#include "t2/hull3d.hpp"

namespace t2cli::algorithms {
namespace {

T2_PROBLEM({"hull3d", "vertices", Input::space});

// The number of vertices of a hull given by its facets.
std::size_t vertex_count(const t2::Facets& F) {
  std::vector<std::uint32_t> v;
  for (const auto& f : F) v.insert(v.end(), f.begin(), f.end());
  std::sort(v.begin(), v.end());
  return static_cast<std::size_t>(std::unique(v.begin(), v.end()) - v.begin());
}

std::function<Timed(BenchInput&)> timed(t2::Hull3dAlgorithm a) {
  return [a](BenchInput& in) -> Timed {
    return [&P = in.points3, a] { return vertex_count(t2::hull_facets_3d(P, a)); };
  };
}

T2_ALGORITHM({.name = "hull3d",  // what `t2 hull3d` runs (Hull3dAlgorithm::quickhull)
              .problem = "hull3d",
              .summary = "t2::convex_hull_3d (R^3; quickhull: farthest point first)",
              .title = "the hull in R^3",
              .time = timed(t2::Hull3dAlgorithm::quickhull),
              .peers = {"cgal", "qhull"}});

T2_ALGORITHM({.name = std::string(t2::name(t2::Hull3dAlgorithm::incremental)),
              .problem = "hull3d",
              .summary = "t2's randomized incremental 3-D hull (conflict lists)",
              .title = "the randomized incremental hull in R^3",
              .time = timed(t2::Hull3dAlgorithm::incremental)});

T2_ALGORITHM({.name = std::string(t2::name(t2::Hull3dAlgorithm::gift_wrap)),
              .problem = "hull3d",
              .summary = "t2's 3-D gift wrapping, O(n) per hull edge",
              .title = "gift wrapping in R^3",
              .time = timed(t2::Hull3dAlgorithm::gift_wrap)});

}  // namespace
}  // namespace t2cli::algorithms
