#pragma once
/// @file polygon.hpp
/// @brief Polygons of T²: vertex lists, segment intersection from four
/// orientations (plus the fifth that T² needs), signed area and orientation.
///
/// A polygon is a cyclic list of vertices p₀, p₁, …, pₙ₋₁ (n ≥ 3); its edges are the segments
/// of T² pᵢpᵢ₊₁ (indices mod n), so no two consecutive vertices may be antipodes. On the
/// sphere a simple polygon cuts T² into two regions: its *positive side* lies to the left of
/// every edge, its *negative side* to the right (seed 000, §5.1). For a counter-clockwise
/// polygon of front points the positive side is the familiar bounded interior.

#include <cmath>
#include <cstddef>
#include <string>
#include <type_traits>
#include <vector>

#include "t2/kernel/error.hpp"
#include "t2/kernel/filter.hpp"
#include "t2/kernel/number.hpp"
#include "t2/kernel/orient.hpp"
#include "t2/kernel/point.hpp"
#include "t2/kernel/segment.hpp"

namespace t2 {

/// A polygon: its vertices in order (the edge from the last vertex back to the first is implied).
template <class T>
using BasicPolygon = std::vector<BasicPoint<T>>;
/// A polygon with `double` coordinates.
using Polygon = BasicPolygon<double>;
/// A polygon with big-integer coordinates.
using ExactPolygon = BasicPolygon<Integer>;

/// True when the closed segments ab and cd of T² have a common point. Exact.
///
/// In ℝ² two segments cross properly iff c, d lie on opposite sides of a∨b and a, b on opposite
/// sides of c∨d: four orientations. In T² that is not enough: the two arcs then meet the
/// common points ±z of the two lines, but ab may hold z while cd holds ¬z (a front segment and
/// the antipode of a crossing one). The fifth condition Δ(a,b,c) = -Δ(c,d,a) picks the
/// same point (it holds automatically for front points). Touching and overlapping segments
/// count as intersecting. Throws `Undefined` if b = ¬a or d = ¬c. (The same test on
/// `t2::Segment` objects is `t2::intersects`; this four-point form is the one chapter 05 teaches.)
template <class T>
bool segments_intersect(const BasicPoint<T>& a, const BasicPoint<T>& b, const BasicPoint<T>& c,
                        const BasicPoint<T>& d) {
  if (a == antipode(b) || c == antipode(d))
    throw Undefined("segment(p, q) is undefined when q = antipode(p)");
  const Sign lc = orient(a, b, c), ld = orient(a, b, d);
  const Sign ka = orient(c, d, a), kb = orient(c, d, b);
  if (lc * ld < 0 && ka * kb < 0) return lc == -ka;
  // Touching or overlapping: then an endpoint of one lies on the other (two arcs shorter than
  // half a great circle that share a point always do that).
  return on_segment(a, b, c) || on_segment(a, b, d) || on_segment(c, d, a) || on_segment(c, d, b);
}

/// The side of T² that holds every vertex of P: `Side::front` or `Side::back`. Throws
/// `Undefined` (naming `what`) when a vertex is on Ω or the vertices lie on both sides.
template <class T>
Side common_side(const BasicPolygon<T>& P, const char* what) {
  if (P.empty()) throw BadInput(std::string(what) + ": the polygon has no vertices");
  const Side s = side_of(P[0]);
  for (const auto& p : P)
    if (side_of(p) == Side::infinity || side_of(p) != s)
      throw Undefined(std::string(what) +
                      " needs every vertex on one side of T2 (front or back), none on the line at infinity");
  return s;
}

namespace detail {

/// The exact sum of `terms`, added in pairs (a balanced tree), not left to right: n fractions
/// with distinct denominators of b bits have a sum whose denominator grows to about n b bits,
/// so a left-to-right sum costs Θ(n² b) while the tree costs O(M(n b) log n), M the cost of a
/// multiplication (a convex polygon's exact area went from quadratic to nearly linear).
inline Rational rational_sum(std::vector<Rational> terms) {
  if (terms.empty()) return 0;
  for (std::size_t width = 1; width < terms.size(); width *= 2)
    for (std::size_t i = 0; i + width < terms.size(); i += 2 * width) terms[i] += terms[i + width];
  return terms[0];
}

}  // namespace detail

/// The number type of `signed_area`: `double` for `double` polygons, `Rational` for exact ones.
template <class T>
using AreaOf = std::conditional_t<std::is_same_v<T, double>, double, Rational>;

/// Twice the signed area of a polygon whose vertices all lie on one side of T² (front or
/// back): Σ (xᵢyᵢ₊₁ − yᵢxᵢ₊₁) / (wᵢwᵢ₊₁) (the shoelace formula), negated on the back side so that
/// its sign agrees with Δ (a back triangle with Δ = +1 has positive area). Exact (a `Rational`)
/// for `Integer` coordinates — an integer when every w = 1; rounded for `double`. Throws
/// `Undefined` when vertices lie on Ω or on both sides: such a region has infinite area.
template <class T>
AreaOf<T> signed_area(const BasicPolygon<T>& P) {
  const Side s = common_side(P, "signed_area(P)");
  const std::size_t n = P.size();
  AreaOf<T> sum = 0;
  if constexpr (std::is_same_v<T, double>) {
    for (std::size_t i = 0; i < n; ++i) {
      const auto& p = P[i];
      const auto& q = P[(i + 1) % n];
      sum += (p.x() / p.w()) * (q.y() / q.w()) - (p.y() / p.w()) * (q.x() / q.w());
    }
  } else {
    std::vector<Rational> terms;
    terms.reserve(n);
    for (std::size_t i = 0; i < n; ++i) {
      const auto& p = P[i];
      const auto& q = P[(i + 1) % n];
      terms.emplace_back(Integer(p.x() * q.y() - p.y() * q.x()), Integer(p.w() * q.w()));
      terms.back().canonicalize();
    }
    sum = detail::rational_sum(std::move(terms));
  }
  return s == Side::back ? AreaOf<T>(-sum) : sum;
}

namespace detail {

/// The sign of twice the signed area of P, for weights w ≠ 0 of one sign (the caller checks
/// that), when the double sum decides it and every coordinate is 0 or has magnitude in
/// [2⁻²⁰⁰, 2²⁰⁰]; ZERO otherwise (then the exact sum must). **Proof of the bound.**
/// The term tᵢ = (aᵢ − bᵢ)/(wᵢwᵢ₊₁), aᵢ = xᵢyᵢ₊₁, bᵢ = yᵢxᵢ₊₁, puts at most four roundings on
/// each of its two monomials: its product, the difference, the product of the weights and the
/// quotient. Each rounding is relative, since none underflows in that range (a nonzero aᵢ − bᵢ
/// is at least 2⁻⁴⁵², the quotient at least 2⁻⁸⁵²) and nothing overflows. So, with γ₅ (one
/// more than needed), |t̂ᵢ − tᵢ| ≤ γ₅ Tᵢ, Tᵢ = (|aᵢ| + |bᵢ|)/|wᵢwᵢ₊₁|; the sum
/// adds n − 1 roundings more, so |Ŝ − S| ≤ γ_{n+4} Σ Tᵢ. T̂ = Σ T̂ᵢ carries at most n + 4
/// roundings too, so (2 n + 10) u T̂ bounds the error for n < 2⁴⁰. (With w = 1 the product of
/// the weights and the quotient are exact, and the bound is merely a little loose.)
inline Sign orientation_filter(const BasicPolygon<double>& P) {
  const auto in_range = [](double c) {
    const double a = std::fabs(c);
    return a == 0 || (a >= 0x1p-200 && a <= 0x1p200);
  };
  const std::size_t n = P.size();
  double S = 0, T = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const auto& p = P[i];
    const auto& q = P[(i + 1) % n];
    if (!in_range(p.w()) || !in_range(p.x()) || !in_range(p.y())) return ZERO;
    const double a = p.x() * q.y(), b = p.y() * q.x(), ww = p.w() * q.w();
    S += (a - b) / ww;
    T += (std::fabs(a) + std::fabs(b)) / std::fabs(ww);
  }
  const double nd = static_cast<double>(n), u = 0x1p-53;
  const double bound = (2 * nd + 10) * u * T;
  if (!std::isfinite(S) || !std::isfinite(bound) || n >= (std::size_t{1} << 40)) return ZERO;
  return S > bound ? POSITIVE : S < -bound ? NEGATIVE : ZERO;
}

}  // namespace detail

/// The exact sign of `signed_area(P)`: POSITIVE for a counter-clockwise front polygon (its
/// positive side is then its bounded interior). Computed in rationals, so exact for `double`
/// input too, after a double filter (`detail::orientation_filter`); the exact sum is added in
/// pairs (`detail::rational_sum`). Same preconditions as `signed_area`.
template <class T>
Sign orientation(const BasicPolygon<T>& P) {
  const Side s = common_side(P, "orientation(P)");
  if constexpr (std::is_same_v<T, double>) {
    const Sign f = detail::orientation_filter(P);
    if (f != ZERO) return s == Side::back ? -f : f;
  }
  const std::size_t n = P.size();
  std::vector<Rational> terms;
  terms.reserve(n);
  auto q_of = [](const T& v) {
    if constexpr (std::is_same_v<T, double>) {
      return to_rational(v);
    } else {
      return Rational(v);
    }
  };
  for (std::size_t i = 0; i < n; ++i) {
    const auto& p = P[i];
    const auto& q = P[(i + 1) % n];
    const Rational pw = q_of(p.w()), px = q_of(p.x()), py = q_of(p.y());
    const Rational qw = q_of(q.w()), qx = q_of(q.x()), qy = q_of(q.y());
    terms.push_back((px * qy - py * qx) / (pw * qw));
  }
  const Sign v = sign_of(detail::rational_sum(std::move(terms)));
  return s == Side::back ? -v : v;
}

/// True when q lies on the boundary of P (on some closed edge, vertices included): the
/// "boundary" case of every point-location routine. Exact. O(n).
template <class T>
bool on_boundary(const BasicPolygon<T>& P, const BasicPoint<T>& q) {
  const std::size_t n = P.size();
  for (std::size_t i = 0; i < n; ++i)
    if (on_segment(P[i], P[(i + 1) % n], q)) return true;
  return false;
}

/// True when P is a simple polygon of T²: n ≥ 3, no two consecutive vertices antipodal or
/// equal, edges that are not neighbours do not meet, and neighbouring edges meet only at their
/// common vertex. Brute force, O(n²); meant for checking input and for tests.
template <class T>
bool is_simple(const BasicPolygon<T>& P) {
  const std::size_t n = P.size();
  if (n < 3) return false;
  for (std::size_t i = 0; i < n; ++i) {
    const auto& a = P[i];
    const auto& b = P[(i + 1) % n];
    if (a == b || a == antipode(b)) return false;
  }
  for (std::size_t i = 0; i < n; ++i) {
    const auto& a = P[i];
    const auto& b = P[(i + 1) % n];
    for (std::size_t j = i + 1; j < n; ++j) {
      const auto& c = P[j];
      const auto& d = P[(j + 1) % n];
      const bool next = (j == i + 1), prev = (i == 0 && j == n - 1);
      if (next) {
        // Edges ab and bd share b: they must not overlap (d on ab, or a on bd).
        if (n == 3 && orient(a, b, d) == ZERO) return false;
        if (on_segment(a, b, d) || on_segment(b, d, a)) return false;
      } else if (prev) {
        // Edges ab and ca (c = P[n-1], d = a) share a.
        if (on_segment(a, b, c) || on_segment(c, a, b)) return false;
      } else if (segments_intersect(a, b, c, d)) {
        return false;
      }
    }
  }
  return true;
}

}  // namespace t2
