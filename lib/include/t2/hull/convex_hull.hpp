#pragma once
/// @file convex_hull.hpp
/// @brief `t2::convex_hull`: the hull of points of T², by any of the six algorithms.

#include <algorithm>
#include <numeric>
#include <span>
#include <string_view>
#include <vector>

#include "t2/hull/chan.hpp"
#include "t2/hull/graham.hpp"
#include "t2/hull/jarvis.hpp"
#include "t2/hull/traits.hpp"
#include "t2/hull/merge.hpp"
#include "t2/hull/monotone.hpp"
#include "t2/hull/quickhull.hpp"

namespace t2 {

/// The hull algorithms of chapter 06.
enum class HullAlgorithm {
  automatic,  ///< Akl–Toussaint + monotone chain for front-only input, else the merge
  merge,      ///< hemisphere hulls merged by bridges (seed 000, Algorithms 3 and 4)
  jarvis,     ///< Jarvis's march, O(nh)
  graham,     ///< Graham's scan, O(n log n)
  quickhull,  ///< Quickhull, O(n log n) on average
  monotone,   ///< Andrew's monotone chain, O(n log n)
  chan,       ///< Chan's algorithm: Graham on groups, Jarvis with tangents, O(n log h)
};

/// Every hull algorithm, in the order of `t2 hull --help`: the list the command line's choices
/// come from (with `name`).
inline constexpr HullAlgorithm hull_algorithms[] = {HullAlgorithm::automatic, HullAlgorithm::merge,
                                                    HullAlgorithm::jarvis,    HullAlgorithm::graham,
                                                    HullAlgorithm::quickhull, HullAlgorithm::monotone,
                                                    HullAlgorithm::chan};

/// The name of an algorithm ("merge", "jarvis", ...), as `t2 hull --algorithm` takes it.
inline std::string_view name(HullAlgorithm a) {
  switch (a) {
    case HullAlgorithm::automatic: return "automatic";
    case HullAlgorithm::merge: return "merge";
    case HullAlgorithm::jarvis: return "jarvis";
    case HullAlgorithm::graham: return "graham";
    case HullAlgorithm::quickhull: return "quickhull";
    case HullAlgorithm::monotone: return "monotone";
    case HullAlgorithm::chan: return "chan";
  }
  return "?";
}

/// The convex hull of the points P of T²: the indices of its strict vertices (a point inside a
/// hull edge is none; of equal points one index is given), counter-clockwise in T², starting
/// anywhere. One point gives one index, collinear points the two ends of their segment, no
/// point none. Throws `NoHull` (a `t2::Undefined`) naming the points that prevent a hull when
/// P lies in no open hemisphere (an antipodal pair, an antipode on a segment or in a triangle of
/// the others). On front-only input this is the classic hull. Exact; the traits K and the trace
/// are those of traits.hpp.
template <class K = HullTraits, class Tr = NoTrace>
std::vector<std::size_t> convex_hull(std::span<const Point> P, HullAlgorithm a = HullAlgorithm::automatic,
                                     Tr&& trace = {}) {
  if (P.empty()) return {};
  const bool front = std::all_of(P.begin(), P.end(), [](const Point& p) { return p.w() > 0; });
  if (a == HullAlgorithm::merge || (a == HullAlgorithm::automatic && !front)) return merge_hull<K>(P, trace);
  if (a == HullAlgorithm::automatic) return akl_toussaint<K>(P, front_chart(), trace);
  std::vector<std::size_t> hull;
  const Chart chart = chart_for<K>(P, hull);  // first an open hemisphere (throws if none)
  if (hull.size() == 1) return hull;  // one point, perhaps repeated
  std::vector<std::size_t> idx(P.size());
  std::iota(idx.begin(), idx.end(), std::size_t{0});
  switch (a) {
    case HullAlgorithm::jarvis: return jarvis<K>(P, idx, chart, trace);
    case HullAlgorithm::graham: return graham<K>(P, idx, chart, trace);
    case HullAlgorithm::quickhull: return quickhull<K>(P, idx, chart, trace);
    case HullAlgorithm::chan: return chan<K>(P, idx, chart, trace);
    default: return monotone_chain<K>(P, std::move(idx), chart, trace);
  }
}

/// The hull of a vector of points (see the span overload).
template <class K = HullTraits, class Tr = NoTrace>
std::vector<std::size_t> convex_hull(const std::vector<Point>& P, HullAlgorithm a = HullAlgorithm::automatic,
                                     Tr&& trace = {}) {
  return convex_hull<K>(std::span<const Point>(P), a, std::forward<Tr>(trace));
}

/// True when the points lie in an open hemisphere of T², i.e. have a hull (Algorithm 3).
template <class K = HullTraits>
bool has_hull(std::span<const Point> P) {
  try {
    merge_hull<K>(P);
    return true;
  } catch (const NoHull&) {
    return false;
  }
}

// The default instantiations are compiled once, in lib/src/hull/convex_hull.cpp.
#ifndef T2_FILTER_STATS  // a program that counts the exact stages compiles its own copy
/// @cond INSTANTIATIONS
extern template std::vector<std::size_t> convex_hull<HullTraits, NoTrace>(std::span<const Point>, HullAlgorithm,
                                                                          NoTrace&&);
extern template std::vector<std::size_t> convex_hull<HullTraits, NoTrace>(const std::vector<Point>&, HullAlgorithm,
                                                                          NoTrace&&);
/// @endcond
#endif

}  // namespace t2
