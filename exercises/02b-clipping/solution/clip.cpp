// Exercise 02b, reference solution. With s = l·p and t = l·q (exact, in big integers), the
// point αp + βq has l-value αs + βt. Both ≥ 0: the whole segment; both < 0: nothing; one of
// each: the segment crosses l at z = |t|·p + |s|·q (l·z = |t|s + |s|t = 0, and z is in the
// cone because both weights are ≥ 0), and the part on the positive side ends there. A zero end
// on the wrong side's segment is the single point where it touches.
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
  if (same(P, Q)) return s >= 0 ? std::vector<t2::ExactPoint>{P} : std::vector<t2::ExactPoint>{};
  if (s >= 0 && t >= 0) return {P, Q};
  if (s < 0 && t < 0) return {};
  if (s == 0) return {P};  // t < 0: only p
  if (t == 0) return {Q};  // s < 0: only q
  const t2::Integer a = abs_of(t), b = abs_of(s);
  const t2::ExactPoint z(a * P.w() + b * Q.w(), a * P.x() + b * Q.x(), a * P.y() + b * Q.y());
  if (s > 0) return {P, z};
  return {z, Q};
}

}  // namespace ex02b
