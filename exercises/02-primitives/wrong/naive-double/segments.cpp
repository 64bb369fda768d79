// Wrong on purpose: the right T² algebra (the cone αp + βq, Cramer's rule for α and β), but
// every determinant is evaluated in doubles. Within a few units in the last place of the line of
// p and q the rounded determinant comes out 0 (or of the wrong sign), so points just off the
// line are said to be on the segment.
#include "segments.hpp"

#include <t2/kernel/error.hpp>

namespace ex02 {

namespace {

int sgn(double v) { return (v > 0) - (v < 0); }

bool same(const t2::Point& p, const t2::Point& q) {
  return p.w() * q.x() == p.x() * q.w() && p.w() * q.y() == p.y() * q.w() && p.x() * q.y() == p.y() * q.x() &&
         p.w() * q.w() + p.x() * q.x() + p.y() * q.y() > 0;
}

double dot_of_crosses(const t2::Point& u, const t2::Point& v, const t2::Point& s, const t2::Point& t) {
  const auto dot = [](const t2::Point& a, const t2::Point& b) { return a.w() * b.w() + a.x() * b.x() + a.y() * b.y(); };
  return dot(u, s) * dot(v, t) - dot(u, t) * dot(v, s);
}

}  // namespace

Shape shape(const t2::Point& p, const t2::Point& q) {
  const t2::Point np(-p.w(), -p.x(), -p.y());
  if (same(np, q)) throw t2::Undefined("segment(p, q) is undefined when q = antipode(p)");
  if (same(p, q)) return Shape::point;
  const int a = sgn(p.w()), b = sgn(q.w());
  if (a == 0 && b == 0) return Shape::at_infinity;
  if (a == 0 || b == 0) return a + b > 0 ? Shape::ray_front : Shape::ray_back;
  if (a != b) return Shape::two_rays;
  return a > 0 ? Shape::front : Shape::back;
}

bool contains(const t2::Point& p, const t2::Point& q, const t2::Point& r) {
  if (same(p, q)) return same(r, p);
  const double det = p.w() * (q.x() * r.y() - q.y() * r.x()) - p.x() * (q.w() * r.y() - q.y() * r.w()) +
                     p.y() * (q.w() * r.x() - q.x() * r.w());
  if (det != 0) return false;
  return dot_of_crosses(r, q, p, q) >= 0 && dot_of_crosses(p, r, p, q) >= 0;
}

}  // namespace ex02
