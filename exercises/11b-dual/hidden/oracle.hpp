#pragma once
// Exercise 11b: exercise 11's oracle for one vertex, copied (each exercise folder is built and
// released on its own; instructors only). It
// works in exact rationals on the drawn positions (x/w, y/w): the circumcentre U by Cramer's rule
// on the two perpendicular bisectors, put on the sites' side when the T² orientation (the sign
// of the drawn one times the sign of w³) is positive and on the other side when it is negative; the
// pole as the left normal (−d_y, d_x) of d = Q − P on the drawn positions. An answer is right
// when it is a positive multiple of the oracle's point.
#include <array>
#include <optional>
#include <string>

#include <t2/kernel/number.hpp>
#include <t2/kernel/point.hpp>

namespace ex11test {

using R = t2::Rational;
using V = std::array<R, 3>;

inline std::array<R, 2> drawn(const t2::Point& p) {
  return {t2::to_rational(p.x()) / t2::to_rational(p.w()), t2::to_rational(p.y()) / t2::to_rational(p.w())};
}
inline int side(const t2::Point& p) { return p.w() > 0 ? 1 : p.w() < 0 ? -1 : 0; }
inline int sgn(const R& r) { return mpq_sgn(r.get_mpq_t()); }

/// The expected vertex, nullopt when undefined.
inline std::optional<V> vertex(const t2::Point& a, const t2::Point& b, const t2::Point& c) {
  const t2::Point* s[3] = {&a, &b, &c};
  std::array<R, 2> P[3];
  for (int i = 0; i < 3; ++i)
    if (side(*s[i]) != 0) P[i] = drawn(*s[i]);
  auto cross = [&](int i, int j, int k) -> R {
    return (P[j][0] - P[i][0]) * (P[k][1] - P[i][1]) - (P[j][1] - P[i][1]) * (P[k][0] - P[i][0]);
  };
  const int sd = side(a);
  const bool one_side = sd != 0 && side(b) == sd && side(c) == sd;
  if (one_side && sgn(cross(0, 1, 2)) != 0) {
    // |U − A|² = |U − B|² = |U − C|²: two linear equations 2(B − A)·U = |B|² − |A|², likewise C.
    const R a1 = 2 * (P[1][0] - P[0][0]), b1 = 2 * (P[1][1] - P[0][1]),
            c1 = P[1][0] * P[1][0] + P[1][1] * P[1][1] - P[0][0] * P[0][0] - P[0][1] * P[0][1];
    const R a2 = 2 * (P[2][0] - P[0][0]), b2 = 2 * (P[2][1] - P[0][1]),
            c2 = P[2][0] * P[2][0] + P[2][1] * P[2][1] - P[0][0] * P[0][0] - P[0][1] * P[0][1];
    const R det = a1 * b2 - a2 * b1;
    const R ux = (c1 * b2 - c2 * b1) / det, uy = (a1 * c2 - a2 * c1) / det;
    const int orient_t2 = sgn(cross(0, 1, 2)) * sd;  // w_a w_b w_c has the sign of sd
    const int w = orient_t2 > 0 ? sd : -sd;
    return V{R(w), w * ux, w * uy};
  }
  for (int i = 0; i < 3; ++i) {
    const int j = (i + 1) % 3, k = (i + 2) % 3;
    if (side(*s[i]) == 0 || side(*s[i]) != side(*s[j])) continue;
    if (one_side) {  // collinear: skip the pair holding the third strictly between its ends
      const R t = (P[k][0] - P[i][0]) * (P[j][0] - P[i][0]) + (P[k][1] - P[i][1]) * (P[j][1] - P[i][1]);
      const R len = (P[j][0] - P[i][0]) * (P[j][0] - P[i][0]) + (P[j][1] - P[i][1]) * (P[j][1] - P[i][1]);
      if (sgn(t) > 0 && t < len) continue;
    }
    return V{R(0), -(P[j][1] - P[i][1]), P[j][0] - P[i][0]};
  }
  return std::nullopt;
}

/// "" when `got` is a positive multiple of the oracle's vertex of (a, b, c), else what is wrong.
inline std::string check(const t2::Point& a, const t2::Point& b, const t2::Point& c, const t2::ExactPoint& got) {
  const auto want = vertex(a, b, c);
  if (!want) return "bad test input: undefined";
  const V g{R(got.w()), R(got.x()), R(got.y())};
  const V& e = *want;
  if (g[0] * e[1] != g[1] * e[0] || g[0] * e[2] != g[2] * e[0] || g[1] * e[2] != g[2] * e[1])
    return "not the point equidistant from the three sites (nor its antipode)";
  if (sgn(g[0] * e[0] + g[1] * e[1] + g[2] * e[2]) <= 0) return "the antipode of the vertex: the wrong side";
  return "";
}

}  // namespace ex11test
