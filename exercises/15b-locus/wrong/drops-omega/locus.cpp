// Wrong on purpose: seed 000's Algorithm 18 as printed, which discards the points of Ω ("no
// point of Ω is in the interior of r"): right on finite rectangles, short on those reaching Ω.
#include "locus.hpp"

#include <algorithm>
#include <cstdint>

#include <t2/kernel/number.hpp>

namespace ex15b {

namespace {

using t2::Rational;

int sign(double v) { return (v > 0) - (v < 0); }

struct Grid {
  std::vector<Rational> xs, ys;  // the distinct drawn x and y, increasing
  std::vector<std::uint32_t> q;  // Q(i, j): the points with x rank < i and y rank < j
  std::uint32_t at(std::size_t i, std::size_t j) const { return q[i * (ys.size() + 1) + j]; }
};

std::size_t below(const std::vector<Rational>& v, const Rational& x) {
  return std::lower_bound(v.begin(), v.end(), x) - v.begin();
}
std::size_t at_most(const std::vector<Rational>& v, const Rational& x) {
  return std::upper_bound(v.begin(), v.end(), x) - v.begin();
}

// Algorithm 17 on the drawn points of one side.
Grid build(const std::vector<std::pair<Rational, Rational>>& pts) {
  Grid g;
  for (const auto& [x, y] : pts) g.xs.push_back(x), g.ys.push_back(y);
  for (auto* v : {&g.xs, &g.ys}) {
    std::sort(v->begin(), v->end());
    v->erase(std::unique(v->begin(), v->end()), v->end());
  }
  const std::size_t ny = g.ys.size() + 1;
  g.q.assign((g.xs.size() + 1) * ny, 0);
  for (const auto& [x, y] : pts) ++g.q[(below(g.xs, x) + 1) * ny + below(g.ys, y) + 1];
  for (std::size_t i = 1; i <= g.xs.size(); ++i)
    for (std::size_t j = 1; j < ny; ++j) g.q[i * ny + j] += g.q[(i - 1) * ny + j] + g.q[i * ny + j - 1] - g.q[(i - 1) * ny + j - 1];
  return g;
}

// The interval of one axis: from the corner's drawn c to c + Δ (Δ = [w, x], w ≥ 0).
struct Interval {
  bool lo_inf = false, hi_inf = false;
  Rational lo, hi;
};
Interval interval(double aw, double ac, const t2::T1& d) {
  const Rational c = Rational(ac) / Rational(aw);
  Interval r;
  if (d.w() == 0) {
    (d.x() > 0 ? r.hi_inf : r.lo_inf) = true;
    r.lo = r.hi = c;
    return r;
  }
  const Rational e = c + Rational(d.x()) / Rational(d.w());
  r.lo = std::min(c, e), r.hi = std::max(c, e);
  return r;
}

}  // namespace

std::vector<long> count(const std::vector<t2::Point>& P, const std::vector<t2::IsoRect>& R) {
  std::vector<std::pair<Rational, Rational>> side[2];
  long omega[3][3] = {};  // the points of Ω by (sign x + 1, sign y + 1)
  for (const auto& p : P) {
    if (p.w() == 0) {
      ++omega[sign(p.x()) + 1][sign(p.y()) + 1];
      continue;
    }
    side[p.w() > 0 ? 0 : 1].emplace_back(Rational(p.x()) / Rational(p.w()), Rational(p.y()) / Rational(p.w()));
  }
  const Grid grid[2] = {build(side[0]), build(side[1])};
  std::vector<long> out;
  out.reserve(R.size());
  for (const auto& r : R) {
    const auto& a = r.a();
    const Grid& g = grid[a.w() > 0 ? 0 : 1];
    const Interval X = interval(a.w(), a.x(), r.dx()), Y = interval(a.w(), a.y(), r.dy());
    // Algorithm 18: four binary searches, Lemma 1's strict counts at the lower and left sides.
    const std::size_t i0 = X.lo_inf ? 0 : below(g.xs, X.lo), i1 = X.hi_inf ? g.xs.size() : at_most(g.xs, X.hi);
    const std::size_t j0 = Y.lo_inf ? 0 : below(g.ys, Y.lo), j1 = Y.hi_inf ? g.ys.size() : at_most(g.ys, Y.hi);
    long n = long(g.at(i1, j1)) - long(g.at(i0, j1)) - long(g.at(i1, j0)) + long(g.at(i0, j0));
    (void)omega;
    out.push_back(n);
  }
  return out;
}

}  // namespace ex15b
