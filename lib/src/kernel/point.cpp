#include "t2/kernel/point.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <climits>
#include <cmath>

namespace t2 {

ExactPoint to_exact(const Point& p) {
  // Each coordinate is m·2^e exactly; multiply all three by 2^-emin (a positive factor).
  // Trailing zero bits are stripped first, so small integers stay small: [1, 5, 7] -> [1, 5, 7].
  Dyadic d[3] = {Dyadic(p.w()), Dyadic(p.x()), Dyadic(p.y())};
  for (auto& c : d) {
    if (c.m == 0) continue;
    const auto tz = mpz_scan1(c.m.get_mpz_t(), 0);
    mpz_fdiv_q_2exp(c.m.get_mpz_t(), c.m.get_mpz_t(), tz);
    c.e += static_cast<long>(tz);
  }
  long emin = LONG_MAX;
  for (const auto& c : d)
    if (c.m != 0) emin = std::min(emin, c.e);
  Integer c[3];
  for (int i = 0; i < 3; ++i) {
    if (d[i].m == 0) continue;
    mpz_mul_2exp(c[i].get_mpz_t(), d[i].m.get_mpz_t(), static_cast<unsigned long>(d[i].e - emin));
  }
  return ExactPoint(c[0], c[1], c[2]);
}

Point to_double(const ExactPoint& p) {
  const Integer* c[3] = {&p.w(), &p.x(), &p.y()};
  double f[3];
  long e[3];
  long emax = LONG_MIN;
  for (int i = 0; i < 3; ++i) {
    f[i] = mpz_get_d_2exp(&e[i], c[i]->get_mpz_t());
    if (*c[i] != 0) emax = std::max(emax, e[i]);
  }
  double r[3];
  for (int i = 0; i < 3; ++i) {
    const long shift = e[i] - emax;  // <= 0; the largest coordinate lands in [0.5, 1)
    r[i] = (*c[i] == 0 || shift < -2000) ? 0.0 : std::ldexp(f[i], static_cast<int>(shift));
  }
  return Point(r[0], r[1], r[2]);
}

Point normalized(const Point& p) {
  if (p.w() != 0) {
    const double a = std::fabs(p.w());
    return Point(p.w() > 0 ? 1.0 : -1.0, p.x() / a, p.y() / a);
  }
  const double m = std::max(std::fabs(p.x()), std::fabs(p.y()));
  return Point(0.0, p.x() / m, p.y() / m);
}

std::optional<std::pair<double, double>> to_cartesian(const Point& p) {
  if (p.w() == 0) return std::nullopt;
  return std::make_pair(p.x() / p.w(), p.y() / p.w());
}

std::string to_string(const Point& p) {
  return fmt::format("[{}, {}, {}]", to_string(p.w()), to_string(p.x()), to_string(p.y()));
}

std::string to_string(const ExactPoint& p) {
  return fmt::format("[{}, {}, {}]", p.w().get_str(), p.x().get_str(), p.y().get_str());
}

}  // namespace t2
