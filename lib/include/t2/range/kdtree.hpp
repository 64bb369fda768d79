#pragma once
/// @file kdtree.hpp
/// @brief A kd-tree of points of T² for closed iso-rectangles: counting in O(√n) and
/// reporting in O(√n + k) per query (chapter 15; Bentley 1975; de Berg et al. §5.2).
///
/// **The tree.** Each side of T² gets its own tree on the drawn positions (drawn.hpp); the
/// points of Ω are kept by direction. A tree over m points is implicit in one array: a node
/// owns a range [lo, hi) of it, and unless the range is a leaf (at most `kLeaf` points) the
/// point at mid = (lo + hi) / 2 is the median in the composite order of the node's axis (x at
/// even depth, y at odd; ties broken by the other coordinate, then by index), [lo, mid) are the
/// points before it and [mid + 1, hi) those after. Built by selection (std::nth_element),
/// O(m log m) time, O(m) memory; every comparison exact (window.hpp).
///
/// **A query** walks down from the root with the rectangle's four bounds and four flags, one
/// per side of the node's region known to lie inside the rectangle; a region with all four
/// flags is inside and answers without tests (its points are one range of the array). Chapter
/// 15 proves that O(√m) nodes are visited besides those reported.

#include <cstddef>
#include <functional>
#include <span>
#include <vector>

#include "t2/kernel/bbox.hpp"
#include "t2/kernel/isorect.hpp"
#include "t2/kernel/point.hpp"
#include "t2/range/drawn.hpp"
#include "t2/trace/hook.hpp"

namespace t2 {

/// A static kd-tree of points of T² (see the file comment).
class KdTree {
 public:
  /// The largest leaf: a node of at most this many points is scanned.
  static constexpr std::size_t kLeaf = 8;

  /// Builds one tree per side, O(n log n). Throws `std::length_error` past 2³² − 1 points.
  explicit KdTree(std::span<const Point> points);

  /// The number of points (with repetition) in the closed rectangle r: the number of i with
  /// contains(r, points[i]). O(√n).
  std::size_t count(const ExactIsoRect& r) const;
  /// The indices i with contains(r, points[i]), ascending. O(√n + k log k) for k answers (the
  /// tree reports in O(√n + k); the sort is the k log k).
  std::vector<std::size_t> report(const ExactIsoRect& r) const;
  /// The same report, telling `hook` (trace/hook.hpp) each node the query enters
  /// (`Event::kd_enter`: its positions in `tree_order`, its depth and splitting point, and
  /// whether its region lies inside r) and each point of the tree it reports (`Event::kd_report`),
  /// in the order of the walk; the points of Ω in r are in the answer only. Only this overload
  /// carries trace code; the one above has none.
  /// @param r the closed rectangle
  /// @param hook hears the reports
  std::vector<std::size_t> report(const ExactIsoRect& r, const trace::AnyHook& hook) const;
  /// The tree's nodes and leaves a query of r enters (the quantity the √n bound counts).
  std::size_t visits(const ExactIsoRect& r) const;
  /// The points of side s (0 front, 1 back) in tree order: the implicit tree of the file
  /// comment, for drawing its cuts.
  const std::vector<DrawnPoint>& tree_order(int s) const { return side_[s]; }

 private:
  template <class Visit>
  void walk(const ExactBBox& b, Visit& v) const;
  std::vector<DrawnPoint> side_[2];  ///< per side, the points in tree order
  OmegaPoints omega_;
};

}  // namespace t2
