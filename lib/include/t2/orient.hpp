#pragma once
/// @file orient.hpp
/// @brief Δ(p, q, r): the orientation of three points of T² (seed 000, §4.3.4).

#include "t2/filter.hpp"
#include "t2/point.hpp"

namespace t2 {

/// The 3×3 determinant |p; q; r| of homogeneous coordinates, on any number type.
template <class N>
N det3(const N& a, const N& b, const N& c, const N& d, const N& e, const N& f, const N& g,
       const N& h, const N& i) {
  return a * (e * i - f * h) - b * (d * i - f * g) + c * (d * h - e * g);
}

/// Δ(p, q, r) = sign of the determinant of the three homogeneous triples.
/// POSITIVE when p lies on the positive (left) side of the oriented line q∨r — for three front
/// points this is the usual counter-clockwise turn; ZERO when the three are collinear (which
/// includes p = ±q). Exact for every finite input.
template <class T>
Sign orient(const BasicPoint<T>& p, const BasicPoint<T>& q, const BasicPoint<T>& r) {
  return sign_of_poly([](const auto&... c) { return det3(c...); }, p.w(), p.x(), p.y(), q.w(),
                      q.x(), q.y(), r.w(), r.x(), r.y());
}

/// True when p, q, r lie on a common line of T².
template <class T>
bool collinear(const BasicPoint<T>& p, const BasicPoint<T>& q, const BasicPoint<T>& r) {
  return orient(p, q, r) == ZERO;
}

}  // namespace t2
