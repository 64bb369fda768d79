#pragma once
// Shared helpers of the test suite: scale of random tests and the exact rational oracle.
#include <cstdlib>
#include <random>

#include "t2/t2.hpp"

namespace t2::testing {

/// How many times more cases to run: 1 by default, T2_SCALE under the `long` label.
inline int scale() {
  const char* s = std::getenv("T2_SCALE");
  const int v = s ? std::atoi(s) : 1;
  return v > 0 ? v : 1;
}

/// The oracle: the exact rational value of the 3×3 determinant of homogeneous coordinates,
/// computed independently of the filter (cofactor expansion along the first column).
inline Rational det3_oracle(const Point& p, const Point& q, const Point& r) {
  const Rational a = to_rational(p.w()), b = to_rational(p.x()), c = to_rational(p.y());
  const Rational d = to_rational(q.w()), e = to_rational(q.x()), f = to_rational(q.y());
  const Rational g = to_rational(r.w()), h = to_rational(r.x()), i = to_rational(r.y());
  return a * (e * i - h * f) - d * (b * i - h * c) + g * (b * f - e * c);
}

inline Sign sign_oracle(const Rational& v) { return static_cast<Sign>(sgn(v)); }

/// The point [w, x, y] with coordinates of P's type (Point or ExactPoint), from small integers.
template <class P>
P make(long w, long x, long y) {
  using T = typename P::Coordinate;
  return P(T(w), T(x), T(y));
}

/// The exact rational value of a coordinate of either type.
inline Rational q(const double& v) { return to_rational(v); }
/// The exact rational value of a coordinate of either type.
inline Rational q(const Integer& v) { return Rational(v); }

}  // namespace t2::testing
