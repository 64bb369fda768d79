#pragma once
// Helpers of the primitive tests (segments, triangles, rectangles, circles, affine maps):
// small random integer points in either coordinate type, and exact integer oracles that do
// not use the code under test.
#include <gtest/gtest.h>

#include <array>
#include <random>

#include "testing.hpp"

namespace t2::testing {

/// A point of coordinate type T from small integers.
template <class T>
BasicPoint<T> pt(long w, long x, long y) {
  return BasicPoint<T>(T(w), T(x), T(y));
}

/// Integer coordinates of the same point (a power-of-two multiple: exact for every double).
inline std::array<Integer, 3> coords(const Point& p) {
  const ExactPoint e = to_exact(p);
  return {e.w(), e.x(), e.y()};
}
/// Integer coordinates of an exact point.
inline std::array<Integer, 3> coords(const ExactPoint& p) { return {p.w(), p.x(), p.y()}; }

/// The same point with Integer coordinates.
inline ExactPoint exact(const Point& p) { return to_exact(p); }
/// The same point (already exact).
inline ExactPoint exact(const ExactPoint& p) { return p; }

/// The oracle determinant of three integer triples: oracle.hpp's exact elimination (not det3 of
/// orient.hpp).
inline Integer det_oracle(const std::array<Integer, 3>& a, const std::array<Integer, 3>& b,
                          const std::array<Integer, 3>& c) {
  auto row = [](const std::array<Integer, 3>& r) { return std::array<Rational, 3>{r[0], r[1], r[2]}; };
  return det_oracle<3>({row(a), row(b), row(c)}).get_num();  // an integer
}

/// α·a + β·b on integer triples.
inline std::array<Integer, 3> combo(const Integer& al, const std::array<Integer, 3>& a, const Integer& be,
                                    const std::array<Integer, 3>& b) {
  return {al * a[0] + be * b[0], al * a[1] + be * b[1], al * a[2] + be * b[2]};
}

/// True when the triple is [0, 0, 0].
inline bool is_zero(const std::array<Integer, 3>& a) { return a[0] == 0 && a[1] == 0 && a[2] == 0; }

/// u = λv for some λ > 0 (oracle equality of points, by cross products and a dot product).
inline bool same_point(const std::array<Integer, 3>& u, const std::array<Integer, 3>& v) {
  return u[0] * v[1] == u[1] * v[0] && u[0] * v[2] == u[2] * v[0] && u[1] * v[2] == u[2] * v[1] &&
         u[0] * v[0] + u[1] * v[1] + u[2] * v[2] > 0;
}

/// Random small integers in [-m, m].
struct Small {
  std::mt19937_64 rng;
  std::uniform_int_distribution<long> d;
  Small(unsigned long seed, long m) : rng(seed), d(-m, m) {}
  long operator()() { return d(rng); }
  /// A random non-zero triple.
  std::array<long, 3> triple() {
    for (;;) {
      std::array<long, 3> t{d(rng), d(rng), d(rng)};
      if (t[0] != 0 || t[1] != 0 || t[2] != 0) return t;
    }
  }
};

/// A point of type T from a triple of longs.
template <class T>
BasicPoint<T> pt(const std::array<long, 3>& t) {
  return pt<T>(t[0], t[1], t[2]);
}

/// A point of type T from an Integer triple (small values).
template <class T>
BasicPoint<T> pt(const std::array<Integer, 3>& t) {
  if constexpr (std::is_same_v<T, double>) {
    return Point(t[0].get_d(), t[1].get_d(), t[2].get_d());
  } else {
    return ExactPoint(t[0], t[1], t[2]);
  }
}

/// The two coordinate types every template is tested with.
using CoordinateTypes = ::testing::Types<double, Integer>;

}  // namespace t2::testing
