// Wrong on purpose: the angles computed with acos in doubles. Equal angles of congruent triangles
// come out a rounding error apart, and angles that differ by less than that come out equal.
#include "angles.hpp"

#include <cmath>

namespace ex03b {

namespace {

double angle(const t2::Point& a, const t2::Point& b, const t2::Point& c) {
  const double ux = a.x() / a.w() - b.x() / b.w(), uy = a.y() / a.w() - b.y() / b.w();
  const double vx = c.x() / c.w() - b.x() / b.w(), vy = c.y() / c.w() - b.y() / b.w();
  return std::acos((ux * vx + uy * vy) / std::sqrt((ux * ux + uy * uy) * (vx * vx + vy * vy)));
}

}  // namespace

t2::Sign compare_angles(const t2::Point& a, const t2::Point& b, const t2::Point& c, const t2::Point& d,
                        const t2::Point& e, const t2::Point& f) {
  const double x = angle(a, b, c), y = angle(d, e, f);
  return x < y ? t2::NEGATIVE : (x > y ? t2::POSITIVE : t2::ZERO);
}

}  // namespace ex03b
