// Wrong on purpose: right answers by brute force, every point against every rectangle, exact
// (O(nm) comparisons of rationals). Too slow for the many queries the locus method is for.
#include "locus.hpp"

#include <algorithm>

#include <t2/kernel/number.hpp>

namespace ex15b {

namespace {

using t2::Rational;

int sign(double v) { return (v > 0) - (v < 0); }

// Is v (drawn, exact) between the corner's c and c + Δ?
bool within(const Rational& v, const Rational& c, const t2::T1& d) {
  if (d.w() == 0) return d.x() > 0 ? v >= c : v <= c;
  const Rational e = c + Rational(d.x()) / Rational(d.w());
  return std::min(c, e) <= v && v <= std::max(c, e);
}

}  // namespace

std::vector<long> count(const std::vector<t2::Point>& P, const std::vector<t2::IsoRect>& R) {
  std::vector<long> out;
  for (const auto& r : R) {
    const auto& a = r.a();
    const Rational cx = Rational(a.x()) / Rational(a.w()), cy = Rational(a.y()) / Rational(a.w());
    const int sx = sign(r.dx().x()) * sign(a.w()), sy = sign(r.dy().x()) * sign(a.w());
    const bool ix = r.dx().w() == 0, iy = r.dy().w() == 0;
    long n = 0;
    for (const auto& p : P) {
      if (p.w() == 0) {
        const int px = sign(p.x()), py = sign(p.y());
        if (ix && iy) n += (px == 0 || px == sx) && (py == 0 || py == sy);
        else if (ix) n += px == sx && py == 0;
        else if (iy) n += px == 0 && py == sy;
        continue;
      }
      if ((p.w() > 0) != (a.w() > 0)) continue;
      n += within(Rational(p.x()) / Rational(p.w()), cx, r.dx()) && within(Rational(p.y()) / Rational(p.w()), cy, r.dy());
    }
    out.push_back(n);
  }
  return out;
}

}  // namespace ex15b
