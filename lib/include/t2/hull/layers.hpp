#pragma once
/// @file layers.hpp
/// @brief Convex layers ("cascas convexas", seed 003 §4.3.1.3): peel hull after hull.
///
/// Seed 003's definition: S₀ = S, S_{j+1} = S_j − V(CH(S_j)) where V is the set of hull
/// vertices, until nothing is left; the layers are the hulls CH(S_j). Vertices are the strict
/// ones (as everywhere in the course), so a point inside a hull edge stays for a deeper layer,
/// and a point is removed with every point equal to it in T².
///
/// The seed gives two ways, both repeated hulls: with Jarvis's march each layer costs O(n h_j)
/// and the h_j add up to at most n, so O(n²) in all; with Graham's scan each layer costs
/// O(n log n), so O(n² log n) when there are Θ(n) layers. (Chazelle's O(n log n) algorithm is
/// only cited by the seed.) In T² a subset of points in an open hemisphere lies in that
/// hemisphere too: one chart (traits.hpp) serves every layer, and the existence test runs once.

#include <cstddef>
#include <numeric>
#include <span>
#include <string_view>
#include <vector>

#include "t2/hull/graham.hpp"
#include "t2/hull/jarvis.hpp"
#include "t2/hull/traits.hpp"
#include "t2/hull/merge.hpp"

namespace t2 {

/// How `convex_layers` computes each layer (seed 003 gives both).
enum class LayersMethod {
  jarvis,  ///< Jarvis's march on what is left: O(n²) in all
  graham,  ///< Graham's scan on what is left: O(n² log n) in all
};

/// Both methods, the default first: the list the command line's choices come from.
inline constexpr LayersMethod layers_methods[] = {LayersMethod::jarvis, LayersMethod::graham};

/// The name of a method ("jarvis", "graham"), as `t2 layers --method` takes it.
constexpr std::string_view name(LayersMethod m) { return m == LayersMethod::jarvis ? "jarvis" : "graham"; }

/// The convex layers of the points P: layer j holds the strict hull vertices of what the layers
/// before it left (indices into P, counter-clockwise in T², one index for equal points). Throws
/// `NoHull` when P lies in no open hemisphere (then not even the outer layer exists).
template <class K = HullTraits>
std::vector<std::vector<std::size_t>> convex_layers(std::span<const Point> P,
                                                    LayersMethod method = LayersMethod::jarvis) {
  std::vector<std::vector<std::size_t>> layers;
  std::vector<std::size_t> hull;
  const Chart chart = chart_for<K>(P, hull);  // throws NoHull
  //> layers
  std::vector<std::size_t> left(P.size());
  std::iota(left.begin(), left.end(), std::size_t{0});
  while (!left.empty()) {
    std::vector<std::size_t> layer = method == LayersMethod::jarvis
                                         ? jarvis<K>(P, left, chart)
                                         : graham<K>(P, left, chart);
    std::vector<std::size_t> rest;  // S_{j+1}: what is not equal to a vertex of the layer
    for (std::size_t i : left) {
      bool vertex = false;
      for (std::size_t v : layer) vertex = vertex || K::equal(P[i], P[v]);
      if (!vertex) rest.push_back(i);
    }
    layers.push_back(std::move(layer));
    left = std::move(rest);
  }
  //< layers
  return layers;
}

// The default instantiation is compiled once, in lib/src/hull/convex_hull.cpp.
#ifndef T2_FILTER_STATS  // a program that counts the exact stages compiles its own copy
/// @cond INSTANTIATIONS
extern template std::vector<std::vector<std::size_t>> convex_layers<HullTraits>(std::span<const Point>, LayersMethod);
/// @endcond
#endif

}  // namespace t2
