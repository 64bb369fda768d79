#pragma once
// The exact rational oracle of the test suite, written independently of the library's
// predicates: every value is a GMP rational (mpq), no filter, no expansion, no shared formula.
#include <algorithm>
#include <array>
#include <stdexcept>
#include <utility>

#include "t2/kernel/number.hpp"
#include "t2/kernel/point.hpp"
#include "t2/kernel/t1.hpp"

namespace t2::testing {

/// The exact rational value of a coordinate of either type.
inline Rational q(const double& v) { return to_rational(v); }
/// The exact rational value of a coordinate of either type.
inline Rational q(const Integer& v) { return Rational(v); }

/// The sign of a rational.
inline Sign sign_oracle(const Rational& v) { return static_cast<Sign>(sgn(v)); }

/// The sign of a − b.
inline Sign compare_oracle(const Rational& a, const Rational& b) { return static_cast<Sign>((a > b) - (a < b)); }

/// The normalized (x, y) of a homogeneous triple: divided by |w|, or by max(|x|, |y|) on Ω
/// (lexicographic.hpp).
inline std::array<Rational, 2> normal_xy(const std::array<Rational, 3>& p) {
  const Rational s = p[0] != 0 ? Rational(abs(p[0])) : std::max(Rational(abs(p[1])), Rational(abs(p[2])));
  return {Rational(p[1] / s), Rational(p[2] / s)};
}

/// The xy order of lexicographic.hpp on two homogeneous triples (normalized x, then y).
inline Sign xy_oracle(const std::array<Rational, 3>& p, const std::array<Rational, 3>& q) {
  const auto a = normal_xy(p), b = normal_xy(q);
  return a[0] != b[0] ? compare_oracle(a[0], b[0]) : compare_oracle(a[1], b[1]);
}

/// The exact homogeneous triple of a point of either type.
template <class P>
std::array<Rational, 3> triple(const P& p) {
  return {q(p.w()), q(p.x()), q(p.y())};
}

/// A drawn (Cartesian) position (X, Y), exactly.
using Pos = std::array<Rational, 2>;

/// The drawn position (x/w, y/w) of a proper point, exactly.
template <class P>
Pos pos(const P& p) {
  return {Rational(q(p.x()) / q(p.w())), Rational(q(p.y()) / q(p.w()))};
}
/// The drawn position of a proper point given by its integer triple [w, x, y].
inline Pos pos(const std::array<Integer, 3>& p) { return {Rational(p[1]) / p[0], Rational(p[2]) / p[0]}; }

/// The finite value x/w of a point of T¹ with w ≠ 0, exactly.
template <class T>
Rational value(const BasicT1<T>& v) {
  return q(v.x()) / q(v.w());
}

/// The squared Euclidean distance of two positions.
inline Rational sq(const Pos& a, const Pos& b) {
  const Rational dx = a[0] - b[0], dy = a[1] - b[1];
  return dx * dx + dy * dy;
}

/// The determinant of an n×n rational matrix by Gaussian elimination with exact division
/// (no cofactor formula shared with the library).
template <std::size_t N>
Rational det_oracle(std::array<std::array<Rational, N>, N> m) {
  Rational det = 1;
  for (std::size_t k = 0; k < N; ++k) {
    std::size_t p = k;
    while (p < N && m[p][k] == 0) ++p;
    if (p == N) return 0;
    if (p != k) {
      std::swap(m[p], m[k]);
      det = -det;
    }
    det *= m[k][k];
    for (std::size_t i = k + 1; i < N; ++i) {
      const Rational f = m[i][k] / m[k][k];
      for (std::size_t j = k; j < N; ++j) m[i][j] -= f * m[k][j];
    }
  }
  return det;
}

/// The 3×3 determinant of the homogeneous triples of p, q, r (Δ of seed 000, §4.3.4).
template <class P>
Rational det3_oracle(const P& p, const P& q, const P& r) {
  return det_oracle<3>({triple(p), triple(q), triple(r)});
}

/// Δ(p, q, r), exactly.
template <class P>
Sign orient_oracle(const P& p, const P& q, const P& r) {
  return sign_oracle(det3_oracle(p, q, r));
}

/// The lifted determinant with rows [X, Y, X² + Y², 1] of the drawn positions, times the sign
/// of w² > 0 — i.e. the Euclidean in-circle sign of four proper points (positive when d is
/// inside the circle through a, b, c turning counter-clockwise on the drawing).
template <class P>
Sign lifted_oracle(const P& a, const P& b, const P& c, const P& d) {
  auto row = [](const P& p) {
    const auto [x, y] = pos(p);
    return std::array<Rational, 4>{x, y, x * x + y * y, Rational(1)};
  };
  return sign_oracle(det_oracle<4>({row(a), row(b), row(c), row(d)}));
}

/// The in-circle sign of d for a, b, c not all proper on one side (the lunes of incircle.hpp),
/// from the sweep rule alone: the disk centred at the point u of Ω perpendicular to the line of
/// the pair (p, q) — the two points of a, b, c on one side, in their cyclic order, or (c, a)
/// when c is on Ω and a, b on opposite sides — and on its left; on each side the points whose
/// key u·(x, y)/|w| exceeds that of the points of a, b, c on that side (which must agree: the
/// lune passes through them). `Undefined` for the triples incircle.hpp rejects.
template <class P>
Sign in_lune_oracle(const P& a, const P& b, const P& c, const P& d) {
  const P* t[3] = {&a, &b, &c};
  int s[3];
  for (int i = 0; i < 3; ++i) s[i] = sgn(q(t[i]->w()));
  if ((s[0] != 0) + (s[1] != 0) + (s[2] != 0) < 2 || orient_oracle(a, b, c) == ZERO) throw Undefined("no lune");
  const P *p = nullptr, *r = nullptr, *omega = nullptr;  // the pivot pair, and the point of Omega
  for (int i = 0; i < 3; ++i) {
    const int j = (i + 1) % 3;
    if (s[i] != 0 && s[i] == s[j]) p = t[i], r = t[j];
    if (s[i] == 0) omega = t[i];
  }
  if (!p) p = omega, r = t[(std::find(t, t + 3, omega) - t + 1) % 3];  // (c, a) with c on Omega
  const auto [pw, px, py] = triple(*p);
  const auto [rw, rx, ry] = triple(*r);
  const Rational ux = py * rw - pw * ry, uy = pw * rx - px * rw;  // (X, Y) of the line p ∨ r
  auto dot = [&](const P& v) { return Rational(ux * q(v.x()) + uy * q(v.y())); };
  auto key = [&](const P& v) { return Rational(dot(v) / abs(q(v.w()))); };
  int outcome_other = 0;  // for c on Omega with a, b on one side: the other side is all in or all out
  Rational k[3];          // the key of each side: index sign + 1
  bool has[3] = {false, false, false};
  for (int i = 0; i < 3; ++i) {
    if (s[i] == 0) continue;
    const Rational v = key(*t[i]);
    if (has[s[i] + 1] && k[s[i] + 1] != v) throw std::logic_error("the lune misses a point");
    k[s[i] + 1] = v;
    has[s[i] + 1] = true;
  }
  if (omega && p != omega) outcome_other = -sgn(dot(*omega));
  if (omega && p == omega && sgn(dot(*omega)) != 0) throw std::logic_error("the lune misses its vertex");
  const int sd = sgn(q(d.w()));
  if (sd == 0) {
    const int h = sgn(dot(d));  // the open half of Omega centred at u is inside
    if (omega && p != omega && h == sgn(dot(*omega))) return ZERO;  // the half of Omega through c: the circle
    return static_cast<Sign>(h);
  }
  if (!has[sd + 1]) return static_cast<Sign>(outcome_other);
  return static_cast<Sign>(sgn(key(d) - k[sd + 1]));
}

/// The 4×4 determinant with rows [x, y, z, 1] of four points of R³ (seed 004's formula for
/// Volume6; it is −(p₃ − p₀)·((p₁ − p₀) × (p₂ − p₀))).
inline Rational det4_points(const std::array<std::array<double, 3>, 4>& v) {
  std::array<std::array<Rational, 4>, 4> m;
  for (std::size_t i = 0; i < 4; ++i)
    m[i] = {to_rational(v[i][0]), to_rational(v[i][1]), to_rational(v[i][2]), Rational(1)};
  return det_oracle<4>(m);
}

}  // namespace t2::testing
