#pragma once
/// @file locus.hpp
/// @brief Counting the points in iso-rectangles of T² by the locus method (chapter 15; seed
/// 000 §5.9, Algorithms 17 and 18; Preparata–Shamos §2.3.1).
///
/// **The method.** Draw a vertical and a horizontal line through every point of one side: they
/// cut the plane into a grid whose cells all give the same answer to "how many points lie below
/// and to the left" (the *dominance count* Q). Store Q at every grid corner, (n_x + 1)(n_y + 1)
/// numbers for n_x distinct x and n_y distinct y, filled by dynamic programming
/// Q(i, j) = C(i, j) + Q(i − 1, j) + Q(i, j − 1) − Q(i − 1, j − 1) (C: the points at that corner).
/// A closed rectangle [x₀, x₁] × [y₀, y₁] holds
///     N = Q(i₁, j₁) − Q(i₀, j₁) − Q(i₁, j₀) + Q(i₀, j₀),
/// with i₀ the number of distinct x below x₀ and i₁ the number at most x₁ (j likewise), found by
/// four binary searches: inclusion–exclusion on the four quadrants below-left of the corners.
/// O(n log n + n_x n_y) = O(n²) time and space to build, O(log n) per query.
///
/// **In T².** A rectangle of T² lies on one side (isorect.hpp): its proper points are those of
/// its corner a's side with x/w and y/w in its intervals, the same problem as in the plane, so
/// each side gets its own grid (seed 000: "one grid per canonical hemisphere"). The seed then
/// discards the points of Ω, arguing that they lie at most on the boundary of a rectangle. For a
/// *closed* rectangle that reaches Ω they are in it (bbox.hpp: the vertex b or d, or the quarter
/// of Ω from b to d), and `contains` says so; this counter counts them, in O(1): Ω points are
/// kept by direction (drawn.hpp), one list per axis direction and per open quadrant of
/// directions, and a rectangle's part of Ω is one axis direction or a closed quarter (two axis
/// directions and the open quadrant between): one list's size, or three.
///
/// Exact: every comparison is on the exact values x/w (T¹ values, big integers), never on
/// rounded quotients.

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "t2/kernel/isorect.hpp"
#include "t2/kernel/number.hpp"
#include "t2/kernel/point.hpp"
#include "t2/kernel/t1.hpp"
#include "t2/range/drawn.hpp"

namespace t2 {

/// Algorithms 17–18: preprocess once, then count the points in any closed iso-rectangle.
class LocusCounter {
 public:
  /// Builds one grid per side; O(n²) time and memory in the worst case (n distinct x and y).
  explicit LocusCounter(std::span<const Point> points);
  /// The number of points (with repetition) in the closed rectangle r: the number of i with
  /// contains(r, points[i]). O(log n) exact comparisons.
  std::size_t count(const ExactIsoRect& r) const;
  /// The same for a rectangle with double coordinates (converted exactly).
  std::size_t count(const IsoRect& r) const;
  /// The number of stored dominance counts, both sides: the memory is 4 bytes each.
  std::size_t cells() const { return side_[0].q.size() + side_[1].q.size(); }

 private:
  struct Grid {
    std::vector<ExactT1> xs, ys;   ///< distinct x/w and y/w of the side's points, increasing
    std::vector<std::uint32_t> q;  ///< Q(i, j) at q[i * (ys.size() + 1) + j]
    std::uint32_t at(std::size_t i, std::size_t j) const { return q[i * (ys.size() + 1) + j]; }
  };
  Grid side_[2];                           ///< front, back
  OmegaPoints omega_;  ///< the points of Ω, by direction (drawn.hpp)
};

}  // namespace t2
