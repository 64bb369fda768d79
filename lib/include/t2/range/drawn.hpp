#pragma once
/// @file drawn.hpp
/// @brief The points of T² as the range structures store them (chapter 15): each proper point
/// by its drawn position on its own side, the points of Ω by their direction.
///
/// A closed iso-rectangle of T² holds proper points of one side only, those whose drawn
/// coordinates x/w, y/w lie in its two intervals (isorect.hpp), and the points of Ω on its part
/// of Ω: nothing, one axis direction, or a closed quarter of Ω (bbox.hpp). So a range structure
/// keeps one planar structure per side and the points of Ω in nine lists, one per pair of signs
/// (sign x, sign y) of their direction; a rectangle's part of Ω is one list or three.
///
/// A drawn point keeps its homogeneous triple with w > 0 (a back point's triple negated: the
/// same drawn position), never the rounded quotients x/w: the structures compare x₁/w₁ with
/// x₂/w₂ exactly (the T¹ `compare` of t1.hpp), and with plain doubles when both w are 1.

#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "t2/kernel/bbox.hpp"
#include "t2/kernel/point.hpp"

namespace t2 {

/// A proper point of T² drawn on its side: the triple with w > 0, and its index in the input.
struct DrawnPoint {
  double w;            ///< the weight, positive
  double x;            ///< the drawn x is x / w
  double y;            ///< the drawn y is y / w
  std::uint32_t index;  ///< the point's position in the input
};

/// The points of Ω of an input, by the signs of their direction.
class OmegaPoints {
 public:
  /// Files the point p of Ω (w = 0) with its input index.
  void add(const Point& p, std::uint32_t index);
  /// The number of these points in the closed box b (its part of Ω). O(1).
  std::size_t count(const ExactBBox& b) const;
  /// Appends to `out` the indices of these points in the closed box b, in no particular order.
  void report(const ExactBBox& b, std::vector<std::size_t>& out) const;

 private:
  std::array<std::vector<std::uint32_t>, 9> slot_;  ///< by (sign x + 1) * 3 + (sign y + 1)
};

/// An input split by side: the front points, the back points (drawn), the points of Ω.
struct Sides {
  std::vector<DrawnPoint> side[2];  ///< [0] front, [1] back
  OmegaPoints omega;                ///< the points of Ω
};

/// Splits the points by side. Throws `std::length_error` past 2³² − 1 points.
Sides split_sides(std::span<const Point> points);

}  // namespace t2
