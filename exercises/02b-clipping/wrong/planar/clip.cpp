// Wrong on purpose: clipping on the planar drawing. Each end is replaced by the front point drawn
// at the same place (a back point by its antipode), so a segment from the front to the back is
// taken for the finite segment between the two drawn points (the classic perspective artefact), and
// the one-point segment p = q is forgotten.
#include "clip.hpp"

#include <t2/kernel/number.hpp>

namespace ex02b {

namespace {

t2::ExactPoint drawn(const t2::Point& p) {
  return t2::to_exact(p.w() < 0 ? t2::Point(-p.w(), -p.x(), -p.y()) : p);
}
t2::Integer abs_of(const t2::Integer& v) { return v < 0 ? t2::Integer(-v) : v; }

}  // namespace

std::vector<t2::ExactPoint> clip(const t2::Point& p, const t2::Point& q, double W, double X, double Y) {
  const t2::ExactPoint P = drawn(p), Q = drawn(q), L = t2::to_exact(t2::Point(W, X, Y));
  const t2::Integer s = L.w() * P.w() + L.x() * P.x() + L.y() * P.y();
  const t2::Integer t = L.w() * Q.w() + L.x() * Q.x() + L.y() * Q.y();
  if (s >= 0 && t >= 0) return {P, Q};
  if (s < 0 && t < 0) return {};
  if (s == 0) return {P};
  if (t == 0) return {Q};
  const t2::Integer a = abs_of(t), b = abs_of(s);
  const t2::ExactPoint z(a * P.w() + b * Q.w(), a * P.x() + b * Q.x(), a * P.y() + b * Q.y());
  if (s > 0) return {P, z};
  return {z, Q};
}

}  // namespace ex02b
