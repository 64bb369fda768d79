#pragma once
/// @file point_in_polygon.hpp
/// @brief Where a point lies with respect to a polygon: ray casting (ℝ²), winding number
/// (ℝ², extended to T² as winding about the axis q–¬q) and Algorithm 2 of seed 000 §5.1 for
/// simple polygons of T², with its special cases settled by symbolic perturbation.
///
/// Every routine here is exact: it only evaluates the signs Δ (orient) and exact coordinate
/// comparisons, never an intersection point.

#include <cstddef>
#include <stdexcept>

#include "t2/kernel/error.hpp"
#include "t2/kernel/filter.hpp"
#include "t2/kernel/orient.hpp"
#include "t2/kernel/point.hpp"
#include "t2/kernel/polygon.hpp"

namespace t2 {

namespace detail {
/// One of the unit points [1,0,0], [0,1,0], [0,0,1] (j = 0, 1, 2), or [0,1,k] style
/// combinations e_a + k·e_b, as a point of type T.
template <class T>
BasicPoint<T> basis_point(int a, int b, long k) {
  T c[3] = {T(0), T(0), T(0)};
  c[a] = T(1);
  c[b] = T(k);
  return BasicPoint<T>(c[0], c[1], c[2]);
}
/// A unit point e_j with Δ(p, q, e_j) ≠ 0; p ≠ ±q is required (some component of p×q is not 0).
template <class T>
BasicPoint<T> off_line_point(const BasicPoint<T>& p, const BasicPoint<T>& q) {
  for (int j = 0; j < 3; ++j) {
    BasicPoint<T> e = basis_point<T>(j, j, 1);
    if (orient(p, q, e) != ZERO) return e;
  }
  throw std::logic_error("off_line_point: p = +-q");
}
}  // namespace detail

/// Ray casting (the classic planar test): counts the edges of P crossed by the horizontal ray
/// from q towards +x, with the half-open rule "a vertex at the height of q counts as below",
/// so that a ray through a vertex is counted once or twice as it should. Returns POSITIVE when
/// q is inside the bounded region of P, NEGATIVE outside, ZERO on the boundary. Works for any
/// closed polygon (for a self-intersecting one it answers the even–odd rule).
/// Needs P and q on the front side of T² (throws `Undefined` otherwise: in T² the "outside"
/// of a polygon has no meaning without a side, use `locate`). Exact. O(n).
template <class T>
Sign locate_by_ray_casting(const BasicPolygon<T>& P, const BasicPoint<T>& q) {
  const char* rule = "locate_by_ray_casting(P, q) is a planar test: P and q must lie on the front side (w > 0)";
  if (side_of(q) != Side::front) throw Undefined(rule);
  for (const auto& p : P)
    if (side_of(p) != Side::front) throw Undefined(rule);
  if (on_boundary(P, q)) return ZERO;
  // above(p): y_p/w_p > y_q/w_q, i.e. y_p w_q - y_q w_p > 0 (both weights positive).
  auto above = [&q](const BasicPoint<T>& p) {
    return sign_of_poly([](const auto& a, const auto& b) { return a.y * b.w - b.y * a.w; }, p, q) == POSITIVE;
  };
  const std::size_t n = P.size();
  bool inside = false;
  for (std::size_t i = 0; i < n; ++i) {
    const auto& a = P[i];
    const auto& b = P[(i + 1) % n];
    const bool ua = above(a), ub = above(b);
    if (ua == ub) continue;
    // The edge crosses the horizontal line of q; the crossing is right of q when q is left of
    // the edge directed upwards.
    const Sign o = orient(a, b, q);
    if ((ub && o == POSITIVE) || (ua && o == NEGATIVE)) inside = !inside;
  }
  return inside ? POSITIVE : NEGATIVE;
}

/// The winding number of P around q: how many times P turns counter-clockwise around q.
/// For front points it is the classic planar winding number. In T² it is the winding of P
/// around the axis through q and ¬q (as seen from q), defined whenever neither q nor ¬q lies on
/// P; an orientation-preserving projective map does not change it.
///
/// Method: the signed crossings of P with the half great circle M from q through a helper
/// point r to ¬q (for front points: the ray from q). Points on the circle of M are resolved by
/// moving q by an infinitesimal ε towards a helper point n (symbolic perturbation), so no
/// special case remains. Throws `Undefined` when q or ¬q is on P. Exact. O(n) (plus the choice
/// of r, O(n) per rejected candidate, at most n + 1 candidates).
template <class T>
int winding_number(const BasicPolygon<T>& P, const BasicPoint<T>& q) {
  if (on_boundary(P, q) || on_boundary(P, antipode(q)))
    throw Undefined("winding_number(P, q) is undefined when q or antipode(q) lies on the boundary of P");
  // r = e_a + k e_b with Δ(q, e_a, e_b) ≠ 0, so every candidate differs from ±q; pick the first
  // that is not ± a vertex.
  int ia = -1, ib = -1;
  for (int a = 0; a < 3 && ia < 0; ++a)
    for (int b = 0; b < 3; ++b)
      if (a != b && orient(q, detail::basis_point<T>(a, a, 1), detail::basis_point<T>(b, b, 1)) != ZERO) {
        ia = a;
        ib = b;
        break;
      }
  auto is_vertex_pm = [&P](const BasicPoint<T>& r) {
    for (const auto& p : P)
      if (orient(p, r, detail::basis_point<T>(0, 0, 1)) == ZERO && orient(p, r, detail::basis_point<T>(1, 1, 1)) == ZERO &&
          orient(p, r, detail::basis_point<T>(2, 2, 1)) == ZERO)
        return true;  // p = ±r: collinear with r and every unit point
    return false;
  };
  long k = 0;
  BasicPoint<T> r = detail::basis_point<T>(ia, ia, 1);
  while (is_vertex_pm(r)) {
    ++k;
    r = detail::basis_point<T>(ia, ib, k);
  }
  const BasicPoint<T> nn = detail::off_line_point(q, r);
  // The perturbed q_ε = q + ε·nn.  Δ(q_ε, x, y) = Δ(q, x, y) + ε Δ(nn, x, y).
  auto side_L = [&](const BasicPoint<T>& x) {  // sign of Δ(q_ε, r, x), never 0 for x ≠ ±r
    const Sign s = orient(q, r, x);
    return s != ZERO ? s : orient(nn, r, x);
  };
  const std::size_t n = P.size();
  int w = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const auto& a = P[i];
    const auto& b = P[(i + 1) % n];
    const Sign la = side_L(a), lb = side_L(b);
    if (la == lb) continue;
    Sign o = orient(q, a, b);
    if (o == ZERO) o = orient(nn, a, b);
    if (o == ZERO) throw std::logic_error("winding_number: degenerate crossing");
    // The edge crosses the circle of M once, at ±z; it is on M (not on -M) iff Δ(q_ε,a,b) = lb.
    if (o == lb) w += lb;
  }
  return w;
}

/// Where q lies with respect to a simple polygon P of T² (seed 000, §5.1, Algorithm 2):
/// POSITIVE on its positive side (left of the edges), NEGATIVE on its negative side, ZERO on
/// its boundary. Vertices may be anywhere in T² (front, back, on Ω) as long as P is simple.
///
/// The idea of the seed: walk the segment p₀q from a vertex p₀; the side of P it enters when it
/// leaves p₀ follows from three orientations (s, t, b below); each crossing of another edge
/// flips the side. Corrections to the seed, all handled here:
///  - q = ¬p₀ leaves p₀q undefined: another vertex is used as p₀;
///  - when q lies on a line through p₀ and an edge (s = 0 or b = 0), or p₀q passes through
///    vertices or runs along edges, the seed leaves the count undefined ("see [PS85]") and its
///    rule s ← −t is wrong when p₀ is a straight vertex (t = 0); here q is moved by an
///    infinitesimal ε towards a helper point n off the line p₀∨q, which removes all of these
///    cases without changing the answer (q is not on the boundary).
/// Throws `Undefined` when P has fewer than 3 vertices or two consecutive vertices are
/// antipodal (an undefined edge). Exact. O(n). For non-simple P the answer is meaningless.
template <class T>
Sign locate(const BasicPolygon<T>& P, const BasicPoint<T>& q) {
  const std::size_t n = P.size();
  if (n < 3) throw Undefined("locate(P, q) needs a polygon of at least 3 vertices");
  if (on_boundary(P, q)) return ZERO;  // also rejects antipodal consecutive vertices
  const std::size_t k = (P[0] == antipode(q)) ? 1 : 0;
  auto p = [&](std::size_t i) -> const BasicPoint<T>& { return P[(k + i) % n]; };
  const BasicPoint<T>& p0 = p(0);
  //> perturbation
  const BasicPoint<T> nn = detail::off_line_point(p0, q);
  auto oq = [&](const BasicPoint<T>& a, const BasicPoint<T>& b) {  // Δ(q_ε, a, b)
    const Sign s = orient(q, a, b);
    return s != ZERO ? s : orient(nn, a, b);
  };
  //< perturbation
  //> algorithm2-start
  Sign s = oq(p0, p(1));                   // side of p0∨p1 the walk p0→q enters
  const Sign t = orient(p(n - 1), p0, p(1));  // +1: p0 is a convex vertex, -1: reflex
  const Sign b = oq(p(n - 1), p0);         // side of p(n-1)∨p0 the walk enters
  if (s * b == NEGATIVE) {
    if (t == ZERO)
      throw Undefined("locate(P, q) needs a simple polygon (P doubles back at a vertex)");
    s = -t;  // between the two edge lines: inside the wedge iff p0 is reflex
  }
  //< algorithm2-start
  if (s == ZERO) throw std::logic_error("locate: degenerate start");
  //> algorithm2-count
  for (std::size_t i = 1; i + 1 < n; ++i) {
    const BasicPoint<T>& c = p(i);
    const BasicPoint<T>& d = p(i + 1);
    const Sign Lc = -oq(p0, c), Ld = -oq(p0, d);  // Δ(p0, q_ε, x) = -Δ(q_ε, p0, x)
    if (Lc == ZERO || Ld == ZERO || Lc == Ld) continue;  // c or d = ¬p0, or no crossing
    const Sign ka = orient(c, d, p0);
    const Sign kb = oq(c, d);  // Δ(c, d, q_ε) = Δ(q_ε, c, d)
    if (ka * kb == NEGATIVE && Lc == -ka)
      s = -s;  // four orientations, plus the fifth of T²
  }
  //< algorithm2-count
  return s;
}

}  // namespace t2
