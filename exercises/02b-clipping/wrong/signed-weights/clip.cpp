// Wrong on purpose: the crossing point z = t·p − s·q with s = l·p, t = l·q has l·z = 0, so it
// is on the line; but when s > 0 > t it is −(|t|·p + |s|·q), the antipode of the point where the
// segment crosses l: the clipped piece ends on the wrong side of the sphere.
#include "clip.hpp"

#include <t2/kernel/number.hpp>

namespace ex02b {

namespace {

bool same(const t2::ExactPoint& a, const t2::ExactPoint& b) {
  return a.w() * b.x() == a.x() * b.w() && a.w() * b.y() == a.y() * b.w() && a.x() * b.y() == a.y() * b.x() &&
         a.w() * b.w() + a.x() * b.x() + a.y() * b.y() > 0;
}

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
  // The crossing of the two lines, with the weights' signs as they come: t·p − s·q.
  const t2::ExactPoint z(t * P.w() - s * Q.w(), t * P.x() - s * Q.x(), t * P.y() - s * Q.y());
  if (s > 0) return {P, z};
  return {z, Q};
}

}  // namespace ex02b
