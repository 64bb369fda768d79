// Wrong on purpose: equality of the unoriented projective plane P² (parallel triples), which
// forgets the sign: p and ¬p come out equal, and "antipodal" is never true.
#include "classify.hpp"

namespace ex01 {

Where where(const t2::Point& p) {
  if (p.w() > 0) return Where::front;
  if (p.w() < 0) return Where::back;
  return Where::infinity;
}

bool same_point(const t2::Point& p, const t2::Point& q) {
  return p.w() * q.x() == p.x() * q.w() && p.w() * q.y() == p.y() * q.w() && p.x() * q.y() == p.y() * q.x();
}

bool antipodal(const t2::Point&, const t2::Point&) { return false; }

}  // namespace ex01
