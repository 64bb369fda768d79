#pragma once
/// @file affine.hpp
/// @brief Affine (and projective) maps of T² (seed 000, §4.2): 3×3 matrices acting on
/// [w, x, y], w first, applied to every primitive.
///
/// A matrix M maps the point p to Mp. M and αM with α > 0 are the same map of T²; M and −M
/// are not (unlike in P²): −M is M followed by the antipodal map. Affine maps have first row
/// [m, 0, 0] and keep Ω in place; other invertible matrices are projective maps, allowed for
/// points, lines, segments and triangles only. Every constructor and every `transform` is
/// division-free, so exact with `Integer` coordinates (with `double` the products round, like
/// every construction of the library).
///
/// **What maps do to sides and orientation.** Δ(Mp, Mq, Mr) = sign(det M)·Δ(p, q, r): a map
/// with negative determinant (a reflection) turns counter-clockwise into clockwise. An affine
/// map with m < 0 ("negative w-scale") sends every front point to the back side and back
/// points to the front — it is an affine map composed with the antipodal map, e.g. −I itself
/// (det −1) maps each p to ¬p. So `scaling(s, d)` with d < 0, or the translation by a vector
/// "beyond infinity", swap the sides.
///
/// **Lines** transform by the inverse transpose, computed with the adjugate (adj M = det M ·
/// M⁻¹, no division): l' = sign(det M)·l·adj(M) = (a positive multiple of) l·M⁻¹. The factor
/// sign(det M) keeps sides: side(transform(M, l), Mp) = side(l, p) for every p, so the image
/// of a half-plane is the positive side of the image line. (For det M < 0 the image line is
/// therefore join(Mq, Mp), reversed with respect to join(Mp, Mq).)

#include <array>
#include <cmath>
#include <string>
#include <type_traits>
#include <utility>

#include "t2/kernel/bbox.hpp"
#include "t2/kernel/circle.hpp"
#include "t2/kernel/error.hpp"
#include "t2/kernel/filter.hpp"
#include "t2/kernel/isorect.hpp"
#include "t2/kernel/line.hpp"
#include "t2/kernel/orient.hpp"
#include "t2/kernel/point.hpp"
#include "t2/kernel/ray.hpp"
#include "t2/kernel/segment.hpp"
#include "t2/kernel/triangle.hpp"
#include "t2/kernel/vector.hpp"

namespace t2 {

/// An invertible 3×3 matrix acting on [w, x, y] (see the file comment).
template <class T>
class BasicAffine {
 public:
  using Coordinate = T;                           ///< the number type of the entries
  using Matrix = std::array<std::array<T, 3>, 3>;  ///< rows of the matrix, w first

  /// The general map with matrix m (rows; row 0 gives the new w). Throws `Undefined` when m
  /// is singular (it would send a whole line of points to [0, 0, 0]).
  explicit BasicAffine(Matrix m) : m_(std::move(m)) {
    for (const auto& row : m_)
      for (const auto& v : row) require_finite(v, "matrix entry");
    if (determinant_sign() == ZERO) throw Undefined("a map of T2 must be invertible (its determinant is 0)");
  }

  /// The identity.
  static BasicAffine identity() { return BasicAffine({{{T(1), T(0), T(0)}, {T(0), T(1), T(0)}, {T(0), T(0), T(1)}}}); }
  /// The translation by the Cartesian vector (dx, dy).
  static BasicAffine translation(T dx, T dy) {
    return BasicAffine({{{T(1), T(0), T(0)}, {std::move(dx), T(1), T(0)}, {std::move(dy), T(0), T(1)}}});
  }
  /// The translation by the vector v = [w, x, y]: the matrix [[w,0,0],[x,w,0],[y,0,w]], which
  /// maps p to q when v = vector(p, q). Throws `Undefined` for an infinite vector (w = 0).
  /// A vector beyond infinity (w < 0) gives a translation that also swaps the sides.
  static BasicAffine translation(const BasicVector<T>& v) {
    if (v.w() == 0) throw Undefined("translation(v) is undefined for a vector at infinity");
    return BasicAffine({{{v.w(), T(0), T(0)}, {v.x(), v.w(), T(0)}, {v.y(), T(0), v.w()}}});
  }
  /// The uniform scaling about the origin by num/den: [[den,0,0],[0,num,0],[0,0,num]].
  /// num < 0 is a half turn; den < 0 swaps the sides. Throws `Undefined` if num or den is 0.
  static BasicAffine scaling(T num, T den = T(1)) {
    return BasicAffine({{{std::move(den), T(0), T(0)}, {T(0), num, T(0)}, {T(0), T(0), num}}});
  }
  /// The rotation about the origin with sine s/den and cosine c/den, given exactly (no
  /// trigonometry): [[den,0,0],[0,c,−s],[0,s,c]]. Throws `BadInput` unless s² + c² = den²
  /// exactly and den > 0 (e.g. the Pythagorean triple s = 3, c = 4, den = 5).
  static BasicAffine rotation(T s, T c, T den) {
    auto pyth = [](const auto& a, const auto& b, const auto& d) { return a * a + b * b - d * d; };
    if (!(den > 0) || sign_of_poly(pyth, s, c, den) != ZERO)
      throw BadInput("rotation(s, c, den) needs den > 0 and s^2 + c^2 = den^2 exactly");
    return BasicAffine({{{std::move(den), T(0), T(0)}, {T(0), c, T(-s)}, {T(0), s, c}}});
  }
  /// The rotation taking direction (1, 0) to d. With `Integer` coordinates it is exact and
  /// needs dx² + dy² to be a perfect square (else `BadInput`: use `rotation(s, c, den)` with a
  /// rational approximation); with `double` the cosine and sine are rounded.
  static BasicAffine rotation(const BasicDirection<T>& d) {
    if constexpr (std::is_same_v<T, double>) {
      const double h = std::hypot(d.dx(), d.dy());
      return BasicAffine({{{1.0, 0.0, 0.0}, {0.0, d.dx() / h, -d.dy() / h}, {0.0, d.dy() / h, d.dx() / h}}});
    } else {
      const Integer n2 = d.dx() * d.dx() + d.dy() * d.dy();
      if (!mpz_perfect_square_p(n2.get_mpz_t()))
        throw BadInput("exact rotation(d) needs dx^2 + dy^2 to be a perfect square");
      return rotation(d.dy(), d.dx(), Integer(sqrt(n2)));
    }
  }

  /// Entry (i, j) of the matrix.
  const T& m(int i, int j) const { return m_[i][j]; }
  /// The rows of the matrix.
  const Matrix& matrix() const { return m_; }
  /// True when the first row is [m, 0, 0]: the map keeps Ω (an affine map).
  bool is_affine() const { return m_[0][1] == 0 && m_[0][2] == 0; }
  /// The exact sign of det M: NEGATIVE for maps that reverse orientation.
  Sign determinant_sign() const {
    return sign_of_poly(
        [](const auto& a, const auto& b, const auto& c) {
          return det3(a[0], a[1], a[2], b[0], b[1], b[2], c[0], c[1], c[2]);
        },
        m_[0], m_[1], m_[2]);
  }

 private:
  Matrix m_;
};

/// Maps with `double` entries.
using Affine = BasicAffine<double>;
/// Maps with big-integer entries.
using ExactAffine = BasicAffine<Integer>;

/// Composition: (a * b) applies b first, then a.
template <class T>
BasicAffine<T> operator*(const BasicAffine<T>& a, const BasicAffine<T>& b) {
  typename BasicAffine<T>::Matrix r;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) r[i][j] = T(a.m(i, 0) * b.m(0, j) + a.m(i, 1) * b.m(1, j) + a.m(i, 2) * b.m(2, j));
  return BasicAffine<T>(r);
}

/// The adjugate (transposed cofactor matrix): adj(M)·M = det(M)·I, with no division.
template <class T>
typename BasicAffine<T>::Matrix adjugate(const BasicAffine<T>& a) {
  typename BasicAffine<T>::Matrix r;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      const int r0 = (j + 1) % 3, r1 = (j + 2) % 3, c0 = (i + 1) % 3, c1 = (i + 2) % 3;
      r[i][j] = T(a.m(r0, c0) * a.m(r1, c1) - a.m(r0, c1) * a.m(r1, c0));
    }
  return r;
}

/// The inverse map: sign(det M)·adj(M), a positive multiple of M⁻¹ (adj(M) alone would be
/// M⁻¹ followed by the antipodal map when det M < 0).
template <class T>
BasicAffine<T> inverse(const BasicAffine<T>& a) {
  auto r = adjugate(a);
  if (a.determinant_sign() == NEGATIVE)
    for (auto& row : r)
      for (auto& v : row) v = T(-v);
  return BasicAffine<T>(r);
}

/// Mp.
template <class T>
BasicPoint<T> transform(const BasicAffine<T>& a, const BasicPoint<T>& p) {
  auto row = [&](int i) { return T(a.m(i, 0) * p.w() + a.m(i, 1) * p.x() + a.m(i, 2) * p.y()); };
  return BasicPoint<T>(row(0), row(1), row(2));
}

/// The image of an oriented line, sides kept: sign(det M)·l·adj(M) (see the file comment).
template <class T>
BasicLine<T> transform(const BasicAffine<T>& a, const BasicLine<T>& l) {
  const auto adj = adjugate(a);
  const T s = a.determinant_sign() == NEGATIVE ? T(-1) : T(1);
  auto col = [&](int j) { return T(s * (l.W() * adj[0][j] + l.X() * adj[1][j] + l.Y() * adj[2][j])); };
  return BasicLine<T>(col(0), col(1), col(2));
}

/// The segment from Ma to Mb (an invertible map never makes them antipodal).
template <class T>
BasicSegment<T> transform(const BasicAffine<T>& a, const BasicSegment<T>& s) {
  return BasicSegment<T>(transform(a, s.source()), transform(a, s.target()));
}

/// The triangle of the images of the vertices; its orientation is multiplied by sign(det M).
template <class T>
BasicTriangle<T> transform(const BasicAffine<T>& a, const BasicTriangle<T>& t) {
  return BasicTriangle<T>(transform(a, t.vertex(0)), transform(a, t.vertex(1)), transform(a, t.vertex(2)));
}

namespace detail {
template <class T>
void require_affine(const BasicAffine<T>& a, const char* what) {
  if (!a.is_affine())
    throw Undefined(std::string(what) + " needs an affine map: a projective map moves the line at infinity");
}
}  // namespace detail

/// The image of a direction: the point of Ω M[0, dx, dy] (affine maps only), so that
/// transform(M, direction(p, q)) = direction(Mp, Mq).
template <class T>
BasicDirection<T> transform(const BasicAffine<T>& a, const BasicDirection<T>& d) {
  detail::require_affine(a, "transform(direction)");
  return BasicDirection<T>(transform(a, d.point()));
}

/// The image of a vector (affine maps only): the linear part, [|m|w, sign(m)·A(x, y)], so that
/// transform(M, vector(p, q)) = vector(Mp, Mq). Translations leave vectors alone.
template <class T>
BasicVector<T> transform(const BasicAffine<T>& a, const BasicVector<T>& v) {
  detail::require_affine(a, "transform(vector)");
  const T m = a.m(0, 0);
  const T s = m < 0 ? T(-1) : T(1);
  return BasicVector<T>(T(s * m * v.w()), T(s * (a.m(1, 1) * v.x() + a.m(1, 2) * v.y())),
                        T(s * (a.m(2, 1) * v.x() + a.m(2, 2) * v.y())));
}

/// The image of a ray: source Mp, direction M d (affine maps only).
template <class T>
BasicRay<T> transform(const BasicAffine<T>& a, const BasicRay<T>& r) {
  detail::require_affine(a, "transform(ray)");
  return BasicRay<T>(transform(a, r.source()), transform(a, r.direction()));
}

/// The image of an iso-rectangle, for affine maps that keep the axes parallel: the linear
/// part diagonal (Δx' = (a₁₁/m)Δx, Δy' = (a₂₂/m)Δy) or anti-diagonal (x and y swap roles).
/// The orientation is multiplied by sign(det M). Throws `Undefined` for other maps (the image
/// is then not axis-parallel).
template <class T>
BasicIsoRect<T> transform(const BasicAffine<T>& a, const BasicIsoRect<T>& r) {
  detail::require_affine(a, "transform(iso_rect)");
  const T m = a.m(0, 0);
  const T s = m < 0 ? T(-1) : T(1);
  const T am = T(s * m);
  const Sign o = a.determinant_sign() * r.orientation();
  const BasicPoint<T> a2 = transform(a, r.a());
  if (a.m(1, 2) == 0 && a.m(2, 1) == 0) {
    return BasicIsoRect<T>(a2, BasicT1<T>(T(am * r.dx().w()), T(s * a.m(1, 1) * r.dx().x())),
                           BasicT1<T>(T(am * r.dy().w()), T(s * a.m(2, 2) * r.dy().x())), o);
  }
  if (a.m(1, 1) == 0 && a.m(2, 2) == 0) {
    return BasicIsoRect<T>(a2, BasicT1<T>(T(am * r.dy().w()), T(s * a.m(1, 2) * r.dy().x())),
                           BasicT1<T>(T(am * r.dx().w()), T(s * a.m(2, 1) * r.dx().x())), o);
  }
  throw Undefined("transform(iso_rect) needs a map that keeps the axes parallel");
}

/// The image of a bounding box, for the same maps as iso-rectangles (axes kept parallel).
template <class T>
BasicBBox<T> transform(const BasicAffine<T>& a, const BasicBBox<T>& b) {
  const auto r = transform(a, BasicIsoRect<T>(b.a(), b.dx(), b.dy()));
  return BasicBBox<T>(r.a(), r.dx(), r.dy());
}

/// The image of a circle, for similarities (linear part [[a, −b], [b, a]] or [[a, b], [b, −a]]):
/// centre Mc, boundary point Mp, orientation multiplied by sign(det M). Throws `Undefined`
/// for other maps, which turn circles into ellipses.
template <class T>
BasicCircle<T> transform(const BasicAffine<T>& a, const BasicCircle<T>& c) {
  detail::require_affine(a, "transform(circle)");
  const bool rot = a.m(1, 1) == a.m(2, 2) && a.m(1, 2) == -a.m(2, 1);
  const bool refl = a.m(1, 1) == -a.m(2, 2) && a.m(1, 2) == a.m(2, 1);
  if (!rot && !refl) throw Undefined("transform(circle) needs a similarity: other affine maps make ellipses");
  return BasicCircle<T>(transform(a, c.center()), transform(a, c.boundary_point()),
                        a.determinant_sign() * c.orientation());
}

/// "affine[[a, b, c], [d, e, f], [g, h, i]]" (rows, w first).
template <class T>
std::string to_string(const BasicAffine<T>& a) {
  std::string s = "affine[";
  for (int i = 0; i < 3; ++i) {
    s += i ? ", [" : "[";
    for (int j = 0; j < 3; ++j) s += (j ? ", " : "") + to_string(a.m(i, j));
    s += "]";
  }
  return s + "]";
}

}  // namespace t2
