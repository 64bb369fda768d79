// Wrong on purpose: right in T², but the sides l·p and l·q are decided in doubles. A point a
// few units in the last place off the line gets the sign of a rounding error (or 0), so the
// segment is kept, dropped or cut at the wrong end.
#include "clip.hpp"

#include <t2/kernel/number.hpp>

namespace ex02b {

namespace {

bool same(const t2::ExactPoint& a, const t2::ExactPoint& b) {
  return a.w() * b.x() == a.x() * b.w() && a.w() * b.y() == a.y() * b.w() && a.x() * b.y() == a.y() * b.x() &&
         a.w() * b.w() + a.x() * b.x() + a.y() * b.y() > 0;
}

t2::Integer abs_of(const t2::Integer& v) { return v < 0 ? t2::Integer(-v) : v; }

}  // namespace

std::vector<t2::ExactPoint> clip(const t2::Point& p, const t2::Point& q, double W, double X, double Y) {
  const t2::ExactPoint P = t2::to_exact(p), Q = t2::to_exact(q);
  const t2::ExactPoint L = t2::to_exact(t2::Point(W, X, Y));  // the line's coefficients, exactly
  const t2::Integer s = L.w() * P.w() + L.x() * P.x() + L.y() * P.y();
  const t2::Integer t = L.w() * Q.w() + L.x() * Q.x() + L.y() * Q.y();
  // The decisions on the sides, in doubles (rounded); only the crossing point is exact.
  const double sd = W * p.w() + X * p.x() + Y * p.y(), td = W * q.w() + X * q.x() + Y * q.y();
  if (same(P, Q)) return sd >= 0 ? std::vector<t2::ExactPoint>{P} : std::vector<t2::ExactPoint>{};
  if (sd >= 0 && td >= 0) return {P, Q};
  if (sd < 0 && td < 0) return {};
  if (sd == 0) return {P};
  if (td == 0) return {Q};
  const t2::Integer a = abs_of(t), b = abs_of(s);
  const t2::ExactPoint z(a * P.w() + b * Q.w(), a * P.x() + b * Q.x(), a * P.y() + b * Q.y());
  if (sd > 0) return {P, z};
  return {z, Q};
}

}  // namespace ex02b
