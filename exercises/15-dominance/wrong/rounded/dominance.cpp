// Wrong on purpose: compares the rounded quotients x/w in doubles. Sides and strict counts are
// right, but a point drawn at 1/3 and a corner at the double nearest 1/3 compare equal.
#include "dominance.hpp"

#include <t2/kernel/error.hpp>
#include <t2/kernel/number.hpp>

namespace ex15 {

namespace {

using Rational = double;  // rounded, not exact

int side(const t2::Point& p) { return p.w() > 0 ? 1 : p.w() < 0 ? -1 : 0; }

// The points p on side s with drawn p.x ≤ x (< when sx) and p.y ≤ y (< when sy).
long dominated(const std::vector<t2::Point>& P, int s, const Rational& x, const Rational& y, bool sx, bool sy) {
  long n = 0;
  for (const auto& p : P) {
    if (side(p) != s) continue;
    const Rational px = Rational(p.x()) / Rational(p.w()), py = Rational(p.y()) / Rational(p.w());
    const bool in_x = sx ? px < x : px <= x, in_y = sy ? py < y : py <= y;
    if (in_x && in_y) ++n;
  }
  return n;
}

}  // namespace

long dominance(const std::vector<t2::Point>& P, const t2::Point& q, bool strict_x, bool strict_y) {
  if (side(q) == 0) throw t2::Undefined("dominance(): the corner q is on Ω");
  return dominated(P, side(q), Rational(q.x()) / Rational(q.w()), Rational(q.y()) / Rational(q.w()), strict_x,
                   strict_y);
}

long count(const std::vector<t2::Point>& P, const t2::Point& lo, const t2::Point& hi) {
  const int s = side(lo);
  if (s == 0 || side(hi) == 0) throw t2::Undefined("count(): a corner is on Ω");
  if (side(hi) != s) throw t2::Undefined("count(): the corners are on different sides");
  const Rational x0 = Rational(lo.x()) / Rational(lo.w()), y0 = Rational(lo.y()) / Rational(lo.w());
  const Rational x1 = Rational(hi.x()) / Rational(hi.w()), y1 = Rational(hi.y()) / Rational(hi.w());
  // Lemma 1: N = Q(x1, y1) − Q(x0⁻, y1) − Q(x1, y0⁻) + Q(x0⁻, y0⁻).
  return dominated(P, s, x1, y1, false, false) - dominated(P, s, x0, y1, true, false) -
         dominated(P, s, x1, y0, false, true) + dominated(P, s, x0, y0, true, true);
}

}  // namespace ex15
