#pragma once
// The brute-force oracle of the smallest enclosing circle (t2/proximity/enclosing_circle.hpp and
// enclosing_circle_voronoi.hpp), shared by their tests: every circle through one, two or three
// sites, on the exact rationals of the drawn positions.
#include <gtest/gtest.h>

#include <algorithm>
#include <optional>
#include <vector>

#include "oracle.hpp"
#include "t2/kernel/point.hpp"
#include "t2/proximity/enclosing_circle.hpp"

namespace t2::testing {

/// A circle of the oracle: centre and squared radius, exactly.
struct Circ {
  Pos c;
  Rational r2;
};

inline Rational d2(const Pos& a, const Pos& b) {
  const Rational dx = a[0] - b[0], dy = a[1] - b[1];
  return dx * dx + dy * dy;
}

/// The circumcircle of three drawn positions (Cramer's rule on the bisectors), none if collinear.
inline std::optional<Circ> circum(const Pos& a, const Pos& b, const Pos& c) {
  const Rational bx = b[0] - a[0], by = b[1] - a[1], cx = c[0] - a[0], cy = c[1] - a[1];
  const Rational D = 2 * (bx * cy - by * cx);
  if (D == 0) return std::nullopt;
  const Rational b2 = bx * bx + by * by, c2 = cx * cx + cy * cy;
  const Pos z{Rational(a[0] + (cy * b2 - by * c2) / D), Rational(a[1] + (bx * c2 - cx * b2) / D)};
  return Circ{z, d2(z, a)};
}

/// The oracle: the smallest of the circles through one site (all sites equal), two (a diameter)
/// or three that hold every site, on the drawn positions.
inline Circ brute(const std::vector<Point>& P) {
  std::vector<Pos> X;
  for (const auto& p : P) X.push_back(pos(p));
  std::vector<Circ> cand{{X[0], Rational(0)}};
  for (std::size_t i = 0; i < X.size(); ++i)
    for (std::size_t j = i + 1; j < X.size(); ++j) {
      const Pos m{Rational((X[i][0] + X[j][0]) / 2), Rational((X[i][1] + X[j][1]) / 2)};
      cand.push_back({m, d2(m, X[i])});
      for (std::size_t k = j + 1; k < X.size(); ++k)
        if (auto c = circum(X[i], X[j], X[k])) cand.push_back(*c);
    }
  std::optional<Circ> best;
  for (const auto& c : cand) {
    if (!std::all_of(X.begin(), X.end(), [&](const Pos& x) { return d2(x, c.c) <= c.r2; })) continue;
    if (!best || c.r2 < best->r2) best = c;
  }
  return *best;
}

/// Checks the library's answer against the circle `want` of the drawn positions.
inline void expect_circle(const std::vector<Point>& P, const EnclosingCircle& got, const Circ& want) {
  const Sign side = sign_of(P[0].w());
  ASSERT_EQ(sign_of(got.center.w()), side) << "the centre is on the sites' side";
  EXPECT_EQ(pos(std::array<Integer, 3>{got.center.w(), got.center.x(), got.center.y()}), want.c);
  EXPECT_EQ(got.radius2, want.r2);
  Integer g;
  mpz_gcd(g.get_mpz_t(), got.center.w().get_mpz_t(), got.center.x().get_mpz_t());
  mpz_gcd(g.get_mpz_t(), g.get_mpz_t(), got.center.y().get_mpz_t());
  EXPECT_EQ(g, 1) << "reduced";
  std::vector<EnclosingCircle::Index> on;
  for (EnclosingCircle::Index i = 0; i < P.size(); ++i)
    if (d2(pos(P[i]), want.c) == want.r2) on.push_back(i);
  EXPECT_EQ(got.on_circle, on);
  ASSERT_GE(got.support.size(), 1u);
  ASSERT_LE(got.support.size(), 3u);
  EXPECT_TRUE(std::is_sorted(got.support.begin(), got.support.end()));
  for (EnclosingCircle::Index s : got.support) EXPECT_TRUE(std::binary_search(on.begin(), on.end(), s)) << s;
}

}  // namespace t2::testing
