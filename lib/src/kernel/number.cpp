#include "t2/kernel/number.hpp"

#include <fmt/format.h>

#include <cmath>

namespace t2 {

Rational to_rational(double v) {
  // mpq_set_d is exact for every finite double (a double is a dyadic rational).
  Rational r;
  mpq_set_d(r.get_mpq_t(), v);
  return r;
}

// Adding +0.0 turns -0 into 0: antipode([1, 0, 1]) prints as [-1, 0, -1], not [-1, -0, -1].
std::string to_string(double v) { return fmt::format("{}", v + 0.0); }

std::string to_string(const Integer& v) { return v.get_str(); }

void require_finite(double v, const char* what) {
  if (!std::isfinite(v)) throw BadInput(fmt::format("coordinate {} is not a finite number ({})", what, v));
}

}  // namespace t2
