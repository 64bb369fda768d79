// Hostile (issue 29, break 2): right answers through t2's point equality (brought under the
// library's name, since the exercise's headers no longer hold it), instantiated on big
// integers (to_exact is allowed here, t2::operator== is not). Its symbol is
// t2::operator==<__gmp_expr<...>>, which a parser of demangled names read as ">": score 0,
// refused by name.
#include "classify.hpp"
namespace t2 {
template <class T>
bool operator==(const BasicPoint<T>& p, const BasicPoint<T>& q) {
  return p.w() * q.x() == p.x() * q.w() && p.w() * q.y() == p.y() * q.w() && p.x() * q.y() == p.y() * q.x() &&
         sgn(p.w() * q.w() + p.x() * q.x() + p.y() * q.y()) > 0;
}
}  // namespace t2
namespace ex01 {
Where where(const t2::Point& p) { return p.w() > 0 ? Where::front : p.w() < 0 ? Where::back : Where::infinity; }
bool same_point(const t2::Point& p, const t2::Point& q) { return t2::to_exact(p) == t2::to_exact(q); }
bool antipodal(const t2::Point& p, const t2::Point& q) {
  const t2::ExactPoint b = t2::to_exact(q);
  return t2::to_exact(p) == t2::ExactPoint(-b.w(), -b.x(), -b.y());
}
}  // namespace ex01
