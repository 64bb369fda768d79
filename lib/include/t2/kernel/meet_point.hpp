#pragma once
/// @file meet_point.hpp
/// @brief Predicates on a point given as the meet of two lines, without constructing it
/// (Attene's *indirect predicates*): its side of a line, its orientation with two points, and
/// its place in the xy order against another meet or a point.
///
/// **Why.** An intersection point l ∧ m has coordinates of degree 2 in the lines' coefficients
/// (line.hpp: the cross product), so a predicate on the constructed point is a predicate of
/// higher degree in the input. Written directly as a polynomial in the coefficients of l and m,
/// each predicate here is one `sign_of_poly` call: the filter derives its error bound from the
/// polynomial (filter.hpp, "The theorem") and its exact stages decide what the bound cannot.
/// For the sweep of chapter 13 the lines are joins of integer points, so their coefficients
/// usually fit the 52 bits of the double fast path even when the constructed point does not.
///
/// **The polynomials.** With l ∧ m = [w, x, y] = [l.X·m.Y − l.Y·m.X, l.Y·m.W − l.W·m.Y,
/// l.W·m.X − l.X·m.W] (the point `meet` returns, of the two antipodal common points the one for
/// which l, m turn counter-clockwise):
/// - side(n, l ∧ m) = sign of n·(l × m) = det |n; l; m|: degree 1 in each line, 6 monomials;
/// - orient(p, q, l ∧ m) = sign of (p × q)·(l × m) = (p·l)(q·m) − (p·m)(q·l) (Lagrange's
///   identity): degree 1 in each argument;
/// - compare_x(l ∧ m, r) with normalized coordinates as in lexicographic.hpp (x/|w| for a
///   proper point): for proper points 1 and 2, x₁/|w₁| − x₂/|w₂| has the sign of
///   x₁|w₂| − x₂|w₁|, which is s·(x₁w₂ − x₂w₁) when sign w₁ = sign w₂ = s and
///   s₂·(x₁w₂ + x₂w₁) when the signs differ (s₁ = −s₂). Two signs of w (degree (1, 1) each)
///   and one product polynomial of degree (1, 1, 1, 1) for two meets, (1, 1, 1) for a meet and
///   a point. Every one is homogeneous in each argument, so `sign_of_poly` certifies it.
///
/// A meet on Ω (parallel lines) has no proper normalization: these orders then construct the
/// point exactly (Integer coordinates, no division) and use lexicographic.hpp. `l ∧ m` is
/// undefined when l and m are the same line (either orientation): every predicate here then
/// throws `Undefined`, as `meet` does.

#include <type_traits>

#include "t2/kernel/error.hpp"
#include "t2/kernel/filter.hpp"
#include "t2/kernel/lexicographic.hpp"
#include "t2/kernel/line.hpp"
#include "t2/kernel/point.hpp"
#include "t2/kernel/sign.hpp"

namespace t2 {

/// The point l ∧ m of line.hpp's `meet`, kept as its two lines (not constructed).
template <class T>
struct MeetPoint {
  BasicLine<T> l;  ///< the first line
  BasicLine<T> m;  ///< the second line
};

namespace detail {
/// The homogeneous coordinates of l ∧ m as polynomials (line.hpp's cross product).
template <class L>
constexpr auto meet_w(const L& l, const L& m) {
  return l.X * m.Y - l.Y * m.X;
}
template <class L>
constexpr auto meet_x(const L& l, const L& m) {
  return l.Y * m.W - l.W * m.Y;
}
template <class L>
constexpr auto meet_y(const L& l, const L& m) {
  return l.W * m.X - l.X * m.W;
}
/// The dot product of a point (Hom3) and a line (Line3).
template <class P, class L>
constexpr auto dot_pl(const P& p, const L& l) {
  return p.w * l.W + p.x * l.X + p.y * l.Y;
}

}  // namespace detail

/// The sign of w of l ∧ m, without constructing it: POSITIVE when the meet is a front point,
/// ZERO when l and m are parallel (they meet on Ω) or the same line. For two lines oriented
/// from left to right (positive side above), POSITIVE means that m is above l just right of
/// their meet, since l ∧ m is the common point about which l and m turn counter-clockwise.
template <class T>
Sign turn(const BasicLine<T>& l, const BasicLine<T>& m) {
  return sign_of_poly([](const auto& a, const auto& b) { return detail::meet_w(a, b); }, l, m);
}

namespace detail {
/// The sign of w of l ∧ m; throws `Undefined` when l and m are the same line.
template <class T>
Sign meet_w_sign(const MeetPoint<T>& a) {
  const Sign s = turn(a.l, a.m);
  if (s == ZERO && sign_of_poly([](const auto& l, const auto& m) { return meet_x(l, m); }, a.l, a.m) == ZERO &&
      sign_of_poly([](const auto& l, const auto& m) { return meet_y(l, m); }, a.l, a.m) == ZERO)
    throw Undefined("meet(l, m) is undefined when l and m are the same line");
  return s;
}

/// The line with integer coefficients that is the same oriented line as l (a positive power of
/// two times it): what the constructions on Ω use for `double` lines.
inline ExactLine exact_line(const Line& l) { return dual(to_exact(dual(l))); }
inline const ExactLine& exact_line(const ExactLine& l) { return l; }
}  // namespace detail

/// The point l ∧ m constructed: exact on `Integer` lines, exactly computed and rounded once on
/// `double` lines.
template <class T>
BasicPoint<T> point_of(const MeetPoint<T>& a) {
  if constexpr (std::is_same_v<T, double>) {
    return to_double(meet(detail::exact_line(a.l), detail::exact_line(a.m)));
  } else {
    return meet(a.l, a.m);
  }
}

/// n ⋄ (l ∧ m): the side of the line n on which the meet of l and m lies (line.hpp's `side`),
/// without constructing it. Throws `Undefined` when l and m are the same line.
template <class T>
Sign side(const BasicLine<T>& n, const MeetPoint<T>& a) {
  const Sign s = sign_of_poly(
      [](const auto& k, const auto& l, const auto& m) {
        return k.W * detail::meet_w(l, m) + k.X * detail::meet_x(l, m) + k.Y * detail::meet_y(l, m);
      },
      n, a.l, a.m);
  if (s == ZERO) (void)detail::meet_w_sign(a);  // rejects l = ±m, for which the sum is 0 too
  return s;
}

/// Δ(p, q, l ∧ m): the orientation of two points and a meet (orient.hpp), without constructing
/// the meet. Throws `Undefined` when l and m are the same line.
template <class T>
Sign orient(const BasicPoint<T>& p, const BasicPoint<T>& q, const MeetPoint<T>& a) {
  const Sign s = sign_of_poly(
      [](const auto& u, const auto& v, const auto& l, const auto& m) {
        return detail::dot_pl(u, l) * detail::dot_pl(v, m) - detail::dot_pl(u, m) * detail::dot_pl(v, l);
      },
      p, q, a.l, a.m);
  if (s == ZERO) (void)detail::meet_w_sign(a);
  return s;
}

namespace detail {
/// sign(c₁/|w₁| − c₂/|w₂|) from s₁ = sign w₁, s₂ = sign w₂ (both nonzero) and the signs of
/// c₁w₂ − c₂w₁ (`minus`) and c₁w₂ + c₂w₁ (`plus`), evaluated lazily (file comment).
template <class Minus, class Plus>
Sign compare_normalized(Sign s1, Sign s2, Minus minus, Plus plus) {
  return s1 == s2 ? s1 * minus() : s2 * plus();
}

/// compare_x (axis 0) or compare_y (axis 1) of two meets.
template <int Axis, class T>
Sign compare_meets(const MeetPoint<T>& a, const MeetPoint<T>& b) {
  const Sign s1 = meet_w_sign(a), s2 = meet_w_sign(b);
  if (s1 == ZERO || s2 == ZERO) {
    const auto p = meet(exact_line(a.l), exact_line(a.m)), q = meet(exact_line(b.l), exact_line(b.m));
    return Axis == 0 ? compare_x(p, q) : compare_y(p, q);
  }
  constexpr auto c = [](const auto& l, const auto& m) {
    if constexpr (Axis == 0) return meet_x(l, m);
    else return meet_y(l, m);
  };
  return compare_normalized(
      s1, s2,
      [&] {
        return sign_of_poly([](const auto& k, const auto& l, const auto& m, const auto& n) {
          return decltype(c)()(k, l) * meet_w(m, n) - decltype(c)()(m, n) * meet_w(k, l);
        }, a.l, a.m, b.l, b.m);
      },
      [&] {
        return sign_of_poly([](const auto& k, const auto& l, const auto& m, const auto& n) {
          return decltype(c)()(k, l) * meet_w(m, n) + decltype(c)()(m, n) * meet_w(k, l);
        }, a.l, a.m, b.l, b.m);
      });
}

/// compare_x (axis 0) or compare_y (axis 1) of a meet and a point.
template <int Axis, class T>
Sign compare_meet_point(const MeetPoint<T>& a, const BasicPoint<T>& p) {
  const Sign s1 = meet_w_sign(a), s2 = sign_of(p.w());
  if (s1 == ZERO || s2 == ZERO) {
    const auto q = meet(exact_line(a.l), exact_line(a.m));
    const auto r = [&] {
      if constexpr (std::is_same_v<T, double>) return to_exact(p);
      else return p;
    }();
    return Axis == 0 ? compare_x(q, r) : compare_y(q, r);
  }
  constexpr auto c = [](const auto& l, const auto& m) {
    if constexpr (Axis == 0) return meet_x(l, m);
    else return meet_y(l, m);
  };
  constexpr auto pc = [](const auto& r) {
    if constexpr (Axis == 0) return r.x;
    else return r.y;
  };
  return compare_normalized(
      s1, s2,
      [&] {
        return sign_of_poly([](const auto& k, const auto& l, const auto& r) {
          return decltype(c)()(k, l) * r.w - decltype(pc)()(r) * meet_w(k, l);
        }, a.l, a.m, p);
      },
      [&] {
        return sign_of_poly([](const auto& k, const auto& l, const auto& r) {
          return decltype(c)()(k, l) * r.w + decltype(pc)()(r) * meet_w(k, l);
        }, a.l, a.m, p);
      });
}
}  // namespace detail

/// Compares the normalized x coordinates of two meets (lexicographic.hpp's compare_x). Exact.
template <class T>
Sign compare_x(const MeetPoint<T>& a, const MeetPoint<T>& b) {
  return detail::compare_meets<0>(a, b);
}
/// Compares the normalized y coordinates of two meets. Exact.
template <class T>
Sign compare_y(const MeetPoint<T>& a, const MeetPoint<T>& b) {
  return detail::compare_meets<1>(a, b);
}
/// Compares the normalized x coordinates of a meet and a point. Exact.
template <class T>
Sign compare_x(const MeetPoint<T>& a, const BasicPoint<T>& p) {
  return detail::compare_meet_point<0>(a, p);
}
/// Compares the normalized y coordinates of a meet and a point. Exact.
template <class T>
Sign compare_y(const MeetPoint<T>& a, const BasicPoint<T>& p) {
  return detail::compare_meet_point<1>(a, p);
}

/// The xy order (lexicographic.hpp's compare_xy: normalized x, then y, ignoring the side) of
/// two meets. Exact.
template <class T>
Sign compare_xy(const MeetPoint<T>& a, const MeetPoint<T>& b) {
  const Sign s = compare_x(a, b);
  return s != ZERO ? s : compare_y(a, b);
}
/// The xy order of a meet and a point. Exact.
template <class T>
Sign compare_xy(const MeetPoint<T>& a, const BasicPoint<T>& p) {
  const Sign s = compare_x(a, p);
  return s != ZERO ? s : compare_y(a, p);
}
/// The xy order of a point and a meet. Exact.
template <class T>
Sign compare_xy(const BasicPoint<T>& p, const MeetPoint<T>& a) {
  return -compare_xy(a, p);
}

}  // namespace t2
