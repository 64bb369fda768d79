#pragma once
/// @file range_tree.hpp
/// @brief A two-dimensional range tree of points of T² with fractional cascading: counting in
/// O(log n) and reporting in O(log n + k) per closed iso-rectangle (chapter 15; Bentley 1979,
/// Willard and Lueker; de Berg et al. §5.3 and §5.6).
///
/// **The tree.** One per side of T², on the drawn positions (drawn.hpp; the points of Ω are
/// kept by direction). The points of a side, sorted in the composite x order (x, then y, then
/// index), are the leaves of a balanced binary tree: a node owns a range [lo, hi) of that
/// array, split at mid = (lo + hi) / 2. Every node keeps its points sorted in the composite y
/// order (y, then x), in the level array of its depth at positions [lo, hi): that list is the
/// merge of its children's lists, and the merge records, at every position t of the node's
/// list, how many of the first t elements came from the left child. That number is the
/// *bridge* of fractional cascading: the elements of the node's list below a value y₀ are a
/// prefix of length j, and those of the left child below y₀ are the first bridge(j) of its
/// list, those of the right child the first j − bridge(j). So one binary search at the root
/// finds the y-interval, and every node below it follows in O(1).
///
/// O(n log n) time and memory (8 bytes per point per level, ⌈log₂ n⌉ + 1 levels).

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "t2/kernel/bbox.hpp"
#include "t2/kernel/isorect.hpp"
#include "t2/kernel/point.hpp"
#include "t2/range/drawn.hpp"

namespace t2 {

/// A static two-dimensional range tree of points of T² (see the file comment).
class RangeTree {
 public:
  /// Builds one tree per side, O(n log n). Throws `std::length_error` past 2³² − 1 points.
  explicit RangeTree(std::span<const Point> points);

  /// The number of points (with repetition) in the closed rectangle r. O(log n).
  std::size_t count(const ExactIsoRect& r) const;
  /// The indices i with contains(r, points[i]), ascending. O(log n + k log k) (the tree
  /// reports in O(log n + k); the sort is the k log k).
  std::vector<std::size_t> report(const ExactIsoRect& r) const;
  /// The entries of the level arrays, both sides: the memory is 8 bytes each.
  std::size_t entries() const;

 private:
  struct Tree {
    std::vector<DrawnPoint> byx;  ///< the side's points in the composite x order
    /// level[d][k]: the position in `byx` of element k - lo of the y-sorted list of the node of
    /// depth d owning k, and bridge[d][k] its number of left-child elements before k.
    std::vector<std::vector<std::uint32_t>> level, bridge;
  };
  template <class Visit>
  void walk(const ExactBBox& b, Visit& v) const;
  Tree side_[2];
  OmegaPoints omega_;
};

}  // namespace t2
