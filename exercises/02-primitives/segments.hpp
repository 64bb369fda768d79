#pragma once
// Exercise 02: the API you implement in segments.cpp. Do not change this file.
#include <t2/kernel/point.hpp>

namespace ex02 {

/// How the segment pq looks in the planar (two-sided) model.
enum class Shape {
  front,        ///< p and q on the front: an ordinary segment of the front sheet
  back,         ///< p and q on the back: an ordinary segment of the back sheet
  two_rays,     ///< one on each side: a front ray and a back ray meeting at infinity
  ray_front,    ///< one end on Ω, the other on the front: a front ray
  ray_back,     ///< one end on Ω, the other on the back: a back ray
  at_infinity,  ///< both ends on Ω: an arc of Ω itself
  point,        ///< p = q: the one-point segment {p} (as in chapter 02 and in CGAL)
};

/// The shape of segment pq. p = q is allowed (Shape::point); throws t2::Undefined when q = ¬p
/// (no segment is defined).
Shape shape(const t2::Point& p, const t2::Point& q);

/// True when r lies on the closed segment pq of T² (q ≠ ¬p is guaranteed by the caller; when
/// p = q the segment is the one point p). Must be exact for every finite double.
bool contains(const t2::Point& p, const t2::Point& q, const t2::Point& r);

}  // namespace ex02
