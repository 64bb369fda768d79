#pragma once
/// @file triangle.hpp
/// @brief Triangles of T² (seed 000, §4.1.6): three vertices whose convex hull exists.
///
/// In the spherical model the triangle abc is the cone {αa + βb + γc : α, β, γ ≥ 0}. It
/// exists only when each side is a segment (no two vertices antipodal) and, because a
/// triangle is convex, when no vertex's antipode lies on the opposite side: ¬a ∉ bc,
/// ¬b ∉ ac, ¬c ∉ ab. For three non-collinear vertices those conditions always hold (¬a is
/// then not even on the line bc); they bite for collinear ("flat") triangles, whose three
/// sides would otherwise wrap around a whole line; there, for distinct pairwise non-antipodal
/// vertices, the three conditions are equivalent (each says the vertices do not fit in an
/// open half of their common line). Flat triangles that pass them are allowed, as in CGAL:
/// they are the longest of the three sides.

#include <string>
#include <utility>

#include "t2/kernel/error.hpp"
#include "t2/kernel/orient.hpp"
#include "t2/kernel/point.hpp"
#include "t2/kernel/segment.hpp"

namespace t2 {

/// A triangle with vertices a, b, c (in that order).
template <class T>
class BasicTriangle {
 public:
  using Coordinate = T;  ///< the number type of the coordinates

  /// The triangle abc. Throws `Undefined` naming the first precondition of §4.1.6 that fails.
  BasicTriangle(BasicPoint<T> a, BasicPoint<T> b, BasicPoint<T> c)
      : v_{std::move(a), std::move(b), std::move(c)} {
    for (int i = 0; i < 3; ++i) {
      const auto &p = v_[i], &q = v_[(i + 1) % 3];
      if (p == antipode(q)) throw Undefined("triangle(a, b, c) is undefined when two vertices are antipodal");
    }
    if (orient(v_[0], v_[1], v_[2]) == ZERO) {
      static const char* rule[3] = {
          "triangle(a, b, c) is undefined when antipode(a) is on segment bc",
          "triangle(a, b, c) is undefined when antipode(b) is on segment ca",
          "triangle(a, b, c) is undefined when antipode(c) is on segment ab"};
      for (int i = 0; i < 3; ++i)
        if (on_segment(v_[(i + 1) % 3], v_[(i + 2) % 3], antipode(v_[i]))) throw Undefined(rule[i]);
    }
  }
  /// Vertex i (0 = a, 1 = b, 2 = c; i is taken modulo 3, as in CGAL).
  const BasicPoint<T>& vertex(int i) const { return v_[((i % 3) + 3) % 3]; }

 private:
  BasicPoint<T> v_[3];
};

/// Triangles with `double` coordinates.
using Triangle = BasicTriangle<double>;
/// Triangles with big-integer coordinates.
using ExactTriangle = BasicTriangle<Integer>;

/// Δ(a, b, c), the orientation of the vertices (counter-clockwise front vertices give
/// POSITIVE; three back vertices drawn the same way give NEGATIVE); ZERO for a flat triangle.
template <class T>
Sign orientation(const BasicTriangle<T>& t) {
  return orient(t.vertex(0), t.vertex(1), t.vertex(2));
}

/// Where a point is with respect to a closed region.
enum class BoundedSide {
  inside = 1,    ///< in the interior
  boundary = 0,  ///< on the boundary
  outside = -1,  ///< not in the region
};

/// Where p is with respect to the triangle t, exactly. For a proper triangle p = αa + βb + γc
/// has sign α = Δ(p, b, c)·Δ(a, b, c) and so on, so p is inside when the three orientations
/// Δ(a,b,p), Δ(b,c,p), Δ(c,a,p) all equal Δ(a,b,c), on the boundary when none is opposite and
/// some is zero. Valid on the whole of T²: ¬p of an inside p is outside. A flat triangle has
/// no interior: p is on its boundary iff it is on one of its sides.
template <class T>
BoundedSide bounded_side(const BasicTriangle<T>& t, const BasicPoint<T>& p) {
  const auto &a = t.vertex(0), &b = t.vertex(1), &c = t.vertex(2);
  const Sign o = orient(a, b, c);
  if (o == ZERO) {
    return (on_segment(a, b, p) || on_segment(b, c, p) || on_segment(c, a, p)) ? BoundedSide::boundary
                                                                              : BoundedSide::outside;
  }
  const Sign s[3] = {orient(a, b, p), orient(b, c, p), orient(c, a, p)};
  bool zero = false;
  for (Sign x : s) {
    if (x == -o) return BoundedSide::outside;
    if (x == ZERO) zero = true;
  }
  return zero ? BoundedSide::boundary : BoundedSide::inside;
}

/// True when p is in the closed triangle (inside or on the boundary). Exact.
template <class T>
bool contains(const BasicTriangle<T>& t, const BasicPoint<T>& p) {
  return bounded_side(t, p) != BoundedSide::outside;
}

/// "triangle([..], [..], [..])".
template <class T>
std::string to_string(const BasicTriangle<T>& t) {
  return "triangle(" + to_string(t.vertex(0)) + ", " + to_string(t.vertex(1)) + ", " + to_string(t.vertex(2)) + ")";
}

}  // namespace t2
