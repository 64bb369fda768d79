// Must NOT compile: a predicate's points all have one coordinate type. A Point (double) and an
// ExactPoint (GMP integers) in one polynomial would need a conversion that the caller must make
// explicit (to_exact). Built by check_compile_fail.cmake twice: as is (must fail, with the
// library's message) and with -DT2_CONTROL (both ExactPoints, must compile).
#include "t2/kernel/point.hpp"

int main() {
  auto minor = [](const auto& p, const auto& q) { return p.w * q.x - p.x * q.w; };
  const t2::Point p(1, 0.5, 0);
  const t2::ExactPoint q(1, 2, 0);
#ifdef T2_CONTROL
  return static_cast<int>(t2::sign_of_poly(minor, t2::to_exact(p), q));
#else
  return static_cast<int>(t2::sign_of_poly(minor, p, q));
#endif
}
