// Exercise 04, reference solution: every double is an integer times a power of two, and
// t2::to_exact scales the three coordinates of a point by one common power of two, which is a
// positive factor and so keeps the point. The determinant of the integer triples then has the
// sign we want, computed without any rounding.
#include "exact_orient.hpp"

#include <t2/kernel/number.hpp>

namespace ex04 {

t2::Sign orient_exact(const t2::Point& p, const t2::Point& q, const t2::Point& r) {
  const t2::ExactPoint a = t2::to_exact(p), b = t2::to_exact(q), c = t2::to_exact(r);
  const t2::Integer d = a.w() * (b.x() * c.y() - b.y() * c.x()) - a.x() * (b.w() * c.y() - b.y() * c.w()) +
                        a.y() * (b.w() * c.x() - b.x() * c.w());
  return static_cast<t2::Sign>(sgn(d));
}

}  // namespace ex04
