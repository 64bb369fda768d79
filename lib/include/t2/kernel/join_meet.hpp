#pragma once
/// @file join_meet.hpp
/// @brief Predicates on the point (a ∨ b) ∧ (c ∨ d), where two segments' lines cross, given by
/// the four input points and never constructed: its weight sign, its side of a third segment's
/// line, and its place in the xy order against another such point or an input point.
///
/// **Why not meet_point.hpp.** MeetPoint takes the two lines. On `double` points the line a ∨ b
/// is a rounded cross product, and a predicate on rounded lines is not the predicate on the
/// input; on `Integer` lines every predicate pays GMP. Here each predicate is one polynomial in
/// the coordinates of the points themselves (the sweep of chapter 13 keeps its input as
/// doubles), evaluated by `sign_of_poly` with the bound filter.hpp derives from its shape.
///
/// **The polynomials.** join(p, q) = p × q (line.hpp) and meet(l, m) = l × m, so the point is
/// [w, x, y] = (a × b) × (c × d), of degree 1 in each of a, b, c, d; expanded without
/// cancelling, each coordinate is a sum of 2·2·2 = 8 monomials (each line coefficient has 2).
/// - `turn(a, b, c, d)` = sign w: 8 monomials of degree (1, 1, 1, 1);
/// - `orient(p, q, X)` = (p × q)·X: 3·2·8 = 48 monomials, degree 1 in each of 6 points;
/// - `orient(p, X, Y)` = p·(X × Y) of two meets: 384 monomials, degree 1 in each of 9 points;
/// - `compare_x(X, r)` for a point r: with sign w_X = s₁ and sign r.w = s₂ (both nonzero), the
///   normalized x of lexicographic.hpp compares as s₁(x_X·r.w − r.x·w_X) when s₁ = s₂ and
///   s₂(x_X·r.w + r.x·w_X) otherwise (meet_point.hpp's file comment): 2·8 = 16 monomials of
///   degree 1 in each of 5 points;
/// - `compare_x(X, Y)` of two meets: x_X·w_Y ∓ x_Y·w_X, 2·8·8 = 128 monomials of degree 1 in
///   each of 8 points; compare_y likewise.
///
/// **Error bounds.** Every polynomial is multi-homogeneous (degree 1 in every point), so
/// filter.hpp's theorem applies as it stands: with u = 2⁻⁵³, k the roundings met by a monomial
/// (derived at compile time, with `count`) and Mᵢ the largest |coordinate| of point i, the
/// rounded value v errs by at most γ_k·count·Π Mᵢ; the filter's constant is count·k·u·(1+2⁻⁴⁰),
/// trusted for every Mᵢ in [2⁻ᴿ, 2ᴿ], R = ⌊900/D⌋ (D = 4, 6, 9, 5, 8: R = 225, 150, 100, 180, 112).
/// Outside that range, or when the bound cannot decide, filter.hpp's exact stages (integer
/// certificate, semi-static bound, expansions, dyadic GMP numbers) give the exact sign: every
/// predicate here is exact for every finite double. tests/test_join_meet.cpp checks them
/// against GMP rationals on near-degenerate input.
///
/// **Ω and undefined meets.** When a ∨ b and c ∨ d are parallel the point is on Ω (w = 0) and
/// has no proper normalization: the orders then construct it exactly (GMP, no division) and
/// use lexicographic.hpp. When a = ±b, c = ±d or the two lines are the same line, the point is
/// undefined: `join_meet` throws `Undefined`.

#include "t2/kernel/error.hpp"
#include "t2/kernel/filter.hpp"
#include "t2/kernel/lexicographic.hpp"
#include "t2/kernel/line.hpp"
#include "t2/kernel/meet_point.hpp"
#include "t2/kernel/point.hpp"
#include "t2/kernel/sign.hpp"

namespace t2 {

/// The point (a ∨ b) ∧ (c ∨ d) of line.hpp's join and meet, kept as its four points (a view:
/// the points must outlive it) and the sign of its w. Made by `join_meet`.
template <class T>
struct JoinMeet {
  const BasicPoint<T>* a;  ///< the first line is a ∨ b
  const BasicPoint<T>* b;  ///< the second point of the first line
  const BasicPoint<T>* c;  ///< the second line is c ∨ d
  const BasicPoint<T>* d;  ///< the second point of the second line
  Sign w;  ///< the sign of w: POSITIVE for a front point, ZERO on Ω
};

namespace detail {
/// p ∨ q = p × q as the coefficients of a line (line.hpp's join), on a filter stage's numbers.
template <class P>
constexpr auto join_of(const P& p, const P& q) {
  using N = decltype(p.x * q.y - p.y * q.x);
  return Line3<N>{p.x * q.y - p.y * q.x, p.y * q.w - p.w * q.y, p.w * q.x - p.x * q.w};
}
/// The w, x or y (Axis 0, 1, 2) of (a ∨ b) ∧ (c ∨ d) as a polynomial in the four points.
template <int Axis, class P>
constexpr auto join_meet_coordinate(const P& a, const P& b, const P& c, const P& d) {
  const auto l = join_of(a, b), m = join_of(c, d);
  if constexpr (Axis == 0) return meet_w(l, m);
  else if constexpr (Axis == 1) return meet_x(l, m);
  else return meet_y(l, m);
}
}  // namespace detail

namespace detail {
/// A Cartesian point [1, x, y] moved by −o, kept as (x − o.x, y − o.y) (file comment).
struct Moved {
  double x;  ///< x − o.x, rounded
  double y;  ///< y − o.y, rounded
};
}  // namespace detail

/// A moved point is read by the filter as the Hom3 [1, x, y].
template <>
struct Leaves<detail::Moved> {
  using Coordinate = double;  ///< the number type of the coordinates
  /// The point on the stage's number type.
  template <class F>
  static auto map(const detail::Moved& p, F&& leaf) {
    return Hom3<decltype(leaf(1.0))>{leaf(1.0), leaf(p.x), leaf(p.y)};
  }
  /// True when `test` holds for the three coordinates.
  template <class F>
  static bool all(const detail::Moved& p, F&& test) {
    return test(1.0) && test(p.x) && test(p.y);
  }
  /// The point's shape (filter.hpp's derive_bound).
  template <class N>
  static constexpr Hom3<N> shape(const N& leaf) {
    return {leaf, leaf, leaf};
  }
};

namespace detail {
/// filter.hpp's bound of F with D more roundings on every monomial (file comment).
template <class F, class... P>
constexpr StaticBound moved_bound() {
  StaticBound b = derive_bound<P...>(F{});
  b.c += b.count * b.total * 0x1p-53 * (1 + 0x1p-40);  // count·(k + D)·u·(1 + 2⁻⁴⁰), exactly
  return b;
}

/// The exact sign of f, a polynomial invariant under translation, at the points p: first the
/// filter at the points moved by −(the first point) when every w is 1, then sign_of_poly.
template <class F, class P0, class... P>
Sign invariant_sign(F&& f, const P0& p0, const P&... p) {
  if constexpr (std::is_same_v<P0, Point>) {
    if (p0.w() == 1 && (... && (p.w() == 1))) {
      static constexpr StaticBound b = moved_bound<std::decay_t<F>, P0, P...>();
      const double ox = p0.x(), oy = p0.y();
      const auto r = static_filter(b, f, [](double x) { return x; }, Moved{0, 0},
                                   Moved{p.x() - ox, p.y() - oy}...);
      if (r.sign != 2) [[likely]] return static_cast<Sign>(r.sign);
    }
  }
  return sign_of_poly(f, p0, p...);
}
}  // namespace detail

/// The sign of w of (a ∨ b) ∧ (c ∨ d): POSITIVE when, a ∨ b and c ∨ d being oriented from left
/// to right, c ∨ d is above a ∨ b just right of their crossing (meet_point.hpp's `turn` on the
/// two joins); ZERO when the lines are parallel, the same line, or a join is undefined.
template <class T>
Sign turn(const BasicPoint<T>& a, const BasicPoint<T>& b, const BasicPoint<T>& c, const BasicPoint<T>& d) {
  return detail::invariant_sign(
      [](const auto& p, const auto& q, const auto& r, const auto& s) {
        return detail::join_meet_coordinate<0>(p, q, r, s);
      },
      a, b, c, d);
}

/// The point (a ∨ b) ∧ (c ∨ d) with the sign of its w. Throws `Undefined` when it is undefined
/// (a = ±b, c = ±d, or the two joins are the same line: all three coordinates vanish).
template <class T>
JoinMeet<T> join_meet(const BasicPoint<T>& a, const BasicPoint<T>& b, const BasicPoint<T>& c,
                      const BasicPoint<T>& d) {
  const Sign w = turn(a, b, c, d);
  if (w == ZERO &&
      sign_of_poly([](const auto& p, const auto& q, const auto& r, const auto& s) {
        return detail::join_meet_coordinate<1>(p, q, r, s);
      }, a, b, c, d) == ZERO &&
      sign_of_poly([](const auto& p, const auto& q, const auto& r, const auto& s) {
        return detail::join_meet_coordinate<2>(p, q, r, s);
      }, a, b, c, d) == ZERO)
    throw Undefined("(a v b) ^ (c v d) is undefined: a = ±b, c = ±d, or the two joins are the same line");
  return {&a, &b, &c, &d, w};
}

namespace detail {
/// (a ∨ b) ∧ (c ∨ d) for points with w = 1, exactly, with GMP integers reused from call to call
/// (join_meet.cpp): the point of meet(join(a, b), join(c, d)) times a positive factor.
ExactPoint exact_join_meet_cartesian(const Point& a, const Point& b, const Point& c, const Point& d);
}  // namespace detail

/// The point constructed exactly (GMP integers): meet(join(a, b), join(c, d)) of line.hpp, up
/// to a positive factor.
template <class T>
BasicPoint<Integer> to_exact(const JoinMeet<T>& m) {
  if constexpr (std::is_same_v<T, double>) {
    if (m.a->w() == 1 && m.b->w() == 1 && m.c->w() == 1 && m.d->w() == 1)
      return detail::exact_join_meet_cartesian(*m.a, *m.b, *m.c, *m.d);
  }
  const auto exact = [](const BasicPoint<T>& p) {
    if constexpr (std::is_same_v<T, double>) return to_exact(p);
    else return p;
  };
  return meet(join(exact(*m.a), exact(*m.b)), join(exact(*m.c), exact(*m.d)));
}

/// Δ(p, q, X) for X = (a ∨ b) ∧ (c ∨ d): the side of p ∨ q on which X lies (line.hpp's `side`
/// of X on join(p, q)), without constructing X. 48 monomials of degree 1 in each point.
template <class T>
Sign orient(const BasicPoint<T>& p, const BasicPoint<T>& q, const JoinMeet<T>& x) {
  return detail::invariant_sign(
      [](const auto& u, const auto& v, const auto& a, const auto& b, const auto& c, const auto& d) {
        const auto n = detail::join_of(u, v), l = detail::join_of(a, b), m = detail::join_of(c, d);
        return n.W * detail::meet_w(l, m) + n.X * detail::meet_x(l, m) + n.Y * detail::meet_y(l, m);
      },
      p, q, *x.a, *x.b, *x.c, *x.d);
}

/// Δ(p, X, Y) for X = (a ∨ b) ∧ (c ∨ d) and Y = (e ∨ f) ∧ (g ∨ h), neither constructed: the
/// determinant |p; X; Y| = p·(X × Y), 3·2·8·8 = 384 monomials of degree 1 in each of the nine
/// points (invariant under translation, as Δ is). The circular sweep of chapter 13 orders its
/// events around a centre p with it. Exact for every finite double.
template <class T>
Sign orient(const BasicPoint<T>& p, const JoinMeet<T>& x, const JoinMeet<T>& y) {
  return detail::invariant_sign(
      [](const auto& u, const auto& a, const auto& b, const auto& c, const auto& d, const auto& e, const auto& f,
         const auto& g, const auto& h) {
        const auto l = detail::join_of(a, b), m = detail::join_of(c, d);
        const auto n = detail::join_of(e, f), k = detail::join_of(g, h);
        const auto xw = detail::meet_w(l, m), xx = detail::meet_x(l, m), xy = detail::meet_y(l, m);
        const auto yw = detail::meet_w(n, k), yx = detail::meet_x(n, k), yy = detail::meet_y(n, k);
        return u.w * (xx * yy - xy * yx) - u.x * (xw * yy - xy * yw) + u.y * (xw * yx - xx * yw);
      },
      p, *x.a, *x.b, *x.c, *x.d, *y.a, *y.b, *y.c, *y.d);
}

namespace detail {
/// compare_x (Axis 1) or compare_y (Axis 2) of two meets (file comment).
template <int Axis, class T>
Sign compare_join_meets(const JoinMeet<T>& x, const JoinMeet<T>& y) {
  if (x.w == ZERO || y.w == ZERO) {
    const auto p = to_exact(x), q = to_exact(y);
    return Axis == 1 ? compare_x(p, q) : compare_y(p, q);
  }
  return compare_normalized(
      x.w, y.w,
      [&] {
        return invariant_sign([](const auto& a, const auto& b, const auto& c, const auto& d, const auto& e,
                                 const auto& f, const auto& g, const auto& h) {
          return join_meet_coordinate<Axis>(a, b, c, d) * join_meet_coordinate<0>(e, f, g, h) -
                 join_meet_coordinate<Axis>(e, f, g, h) * join_meet_coordinate<0>(a, b, c, d);
        }, *x.a, *x.b, *x.c, *x.d, *y.a, *y.b, *y.c, *y.d);
      },
      [&] {
        return sign_of_poly([](const auto& a, const auto& b, const auto& c, const auto& d, const auto& e,
                               const auto& f, const auto& g, const auto& h) {
          return join_meet_coordinate<Axis>(a, b, c, d) * join_meet_coordinate<0>(e, f, g, h) +
                 join_meet_coordinate<Axis>(e, f, g, h) * join_meet_coordinate<0>(a, b, c, d);
        }, *x.a, *x.b, *x.c, *x.d, *y.a, *y.b, *y.c, *y.d);
      });
}

/// compare_x (Axis 1) or compare_y (Axis 2) of a meet and a point (file comment).
template <int Axis, class T>
Sign compare_join_meet_point(const JoinMeet<T>& x, const BasicPoint<T>& r) {
  const Sign s2 = sign_of(r.w());
  if (x.w == ZERO || s2 == ZERO) {
    const auto p = to_exact(x);
    const auto q = [&] {
      if constexpr (std::is_same_v<T, double>) return to_exact(r);
      else return r;
    }();
    return Axis == 1 ? compare_x(p, q) : compare_y(p, q);
  }
  constexpr auto rc = [](const auto& p) {
    if constexpr (Axis == 1) return p.x;
    else return p.y;
  };
  return compare_normalized(
      x.w, s2,
      [&] {
        return invariant_sign([](const auto& a, const auto& b, const auto& c, const auto& d, const auto& p) {
          return join_meet_coordinate<Axis>(a, b, c, d) * p.w - decltype(rc)()(p) * join_meet_coordinate<0>(a, b, c, d);
        }, *x.a, *x.b, *x.c, *x.d, r);
      },
      [&] {
        return sign_of_poly([](const auto& a, const auto& b, const auto& c, const auto& d, const auto& p) {
          return join_meet_coordinate<Axis>(a, b, c, d) * p.w + decltype(rc)()(p) * join_meet_coordinate<0>(a, b, c, d);
        }, *x.a, *x.b, *x.c, *x.d, r);
      });
}
}  // namespace detail

/// Compares the normalized x coordinates of two meets (lexicographic.hpp's compare_x). Exact.
template <class T>
Sign compare_x(const JoinMeet<T>& x, const JoinMeet<T>& y) {
  return detail::compare_join_meets<1>(x, y);
}
/// Compares the normalized y coordinates of two meets. Exact.
template <class T>
Sign compare_y(const JoinMeet<T>& x, const JoinMeet<T>& y) {
  return detail::compare_join_meets<2>(x, y);
}
/// Compares the normalized x coordinates of a meet and a point. Exact.
template <class T>
Sign compare_x(const JoinMeet<T>& x, const BasicPoint<T>& r) {
  return detail::compare_join_meet_point<1>(x, r);
}
/// Compares the normalized y coordinates of a meet and a point. Exact.
template <class T>
Sign compare_y(const JoinMeet<T>& x, const BasicPoint<T>& r) {
  return detail::compare_join_meet_point<2>(x, r);
}
/// The xy order (lexicographic.hpp's compare_xy, ignoring the side) of two meets. Exact.
template <class T>
Sign compare_xy(const JoinMeet<T>& x, const JoinMeet<T>& y) {
  const Sign s = compare_x(x, y);
  return s != ZERO ? s : compare_y(x, y);
}
/// The xy order of a meet and a point. Exact.
template <class T>
Sign compare_xy(const JoinMeet<T>& x, const BasicPoint<T>& r) {
  const Sign s = compare_x(x, r);
  return s != ZERO ? s : compare_y(x, r);
}
/// The xy order of a point and a meet. Exact.
template <class T>
Sign compare_xy(const BasicPoint<T>& r, const JoinMeet<T>& x) {
  return -compare_xy(x, r);
}

}  // namespace t2
