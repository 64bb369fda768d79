// Exercise 03b, reference solution. With u = w_b·a − w_a·b and v = w_b·c − w_c·b (Cartesian
// parts: positive multiples of the vectors b→a and b→c, since the weights are positive),
// cos ∠abc = (u·v)/(|u||v|). The angle shrinks as the cosine grows, so compare
// k₁ = (u·v)/√(|u|²|v|²) with k₂ likewise: first their signs, then, for equal strict signs,
// (u·v)²·N₂ against (u'·v')²·N₁ (N = |u|²|v|²), the order reversed when both are negative.
// Everything in big integers: exact.
#include "angles.hpp"

#include <t2/kernel/number.hpp>

namespace ex03b {

namespace {

struct Cos {
  t2::Integer dot, norms;  // u·v and |u|²|v|²
};

Cos cosine(const t2::Point& a, const t2::Point& b, const t2::Point& c) {
  const t2::ExactPoint A = t2::to_exact(a), B = t2::to_exact(b), C = t2::to_exact(c);
  const t2::Integer ux = B.w() * A.x() - A.w() * B.x(), uy = B.w() * A.y() - A.w() * B.y();
  const t2::Integer vx = B.w() * C.x() - C.w() * B.x(), vy = B.w() * C.y() - C.w() * B.y();
  return {ux * vx + uy * vy, (ux * ux + uy * uy) * (vx * vx + vy * vy)};
}

int sign(const t2::Integer& v) { return sgn(v); }

}  // namespace

t2::Sign compare_angles(const t2::Point& a, const t2::Point& b, const t2::Point& c, const t2::Point& d,
                        const t2::Point& e, const t2::Point& f) {
  const Cos k1 = cosine(a, b, c), k2 = cosine(d, e, f);
  const int s1 = sign(k1.dot), s2 = sign(k2.dot);
  // A larger cosine is a smaller angle.
  if (s1 != s2) return s1 > s2 ? t2::NEGATIVE : t2::POSITIVE;
  if (s1 == 0) return t2::ZERO;
  const int order = sign(k1.dot * k1.dot * k2.norms - k2.dot * k2.dot * k1.norms);  // |cos₁| vs |cos₂|
  const int cos_order = s1 > 0 ? order : -order;  // sign of cos₁ − cos₂
  return static_cast<t2::Sign>(-cos_order);
}

}  // namespace ex03b
