// Wrong on purpose: exact, but it compares cos² and forgets the sign of the cosine, so an obtuse
// angle is taken for the acute angle with the same |cos| (120° for 60°).
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
  // cos² only: a larger cos² is taken for a smaller angle.
  const int order = sign(k1.dot * k1.dot * k2.norms - k2.dot * k2.dot * k1.norms);
  return static_cast<t2::Sign>(-order);
}

}  // namespace ex03b
