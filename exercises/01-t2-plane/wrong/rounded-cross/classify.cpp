// Wrong on purpose: the right idea (minors zero, dot product positive) in rounded doubles, so
// products that round differently make equal points look different and vice versa; and where()
// forgets the line at infinity.
#include "classify.hpp"

namespace ex01 {

Where where(const t2::Point& p) { return p.w() >= 0 ? Where::front : Where::back; }

bool same_point(const t2::Point& p, const t2::Point& q) {
  const bool par = p.w() * q.x() - p.x() * q.w() == 0 && p.w() * q.y() - p.y() * q.w() == 0 &&
                   p.x() * q.y() - p.y() * q.x() == 0;
  return par && p.w() * q.w() + p.x() * q.x() + p.y() * q.y() > 0;
}

bool antipodal(const t2::Point& p, const t2::Point& q) {
  const bool par = p.w() * q.x() - p.x() * q.w() == 0 && p.w() * q.y() - p.y() * q.w() == 0 &&
                   p.x() * q.y() - p.y() * q.x() == 0;
  return par && p.w() * q.w() + p.x() * q.x() + p.y() * q.y() < 0;
}

}  // namespace ex01
