#pragma once
// Shared helpers of the test suite: scale of random tests, the exact rational oracle (oracle.hpp).
#include <cstdlib>
#include <random>

#include "oracle.hpp"
#include "t2/t2.hpp"

namespace t2::testing {

/// How many times more cases to run: 1 by default, T2_SCALE under the `long` label.
inline int scale() {
  const char* s = std::getenv("T2_SCALE");
  const int v = s ? std::atoi(s) : 1;
  return v > 0 ? v : 1;
}

/// The point [w, x, y] with coordinates of P's type (Point or ExactPoint), from small integers.
template <class P>
P make(long w, long x, long y) {
  using T = typename P::Coordinate;
  return P(T(w), T(x), T(y));
}

}  // namespace t2::testing
