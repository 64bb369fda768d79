// Forbidden (issues 12 and 29): correct answers through t2::antipode and t2's point equality,
// which the exercise asks the student to write. The exercise's headers no longer hold them
// (point_type.hpp has the type only), so the submission brings the library's code under the
// library's names, as a student copying lib/ would; the grader reads the object's symbols:
// score 0, refused by name.
#include "classify.hpp"
namespace t2 {
template <class T>
BasicPoint<T> antipode(const BasicPoint<T>& p) {
  return BasicPoint<T>(-p.w(), -p.x(), -p.y());
}
template <class T>
bool operator==(const BasicPoint<T>& p, const BasicPoint<T>& q) {
  const ExactPoint a = to_exact(p), b = to_exact(q);
  return a.w() * b.x() == a.x() * b.w() && a.w() * b.y() == a.y() * b.w() && a.x() * b.y() == a.y() * b.x() &&
         sgn(a.w() * b.w() + a.x() * b.x() + a.y() * b.y()) > 0;
}
}  // namespace t2
namespace ex01 {
Where where(const t2::Point& p) { return p.w() > 0 ? Where::front : p.w() < 0 ? Where::back : Where::infinity; }
bool same_point(const t2::Point& p, const t2::Point& q) { return p == q; }
bool antipodal(const t2::Point& p, const t2::Point& q) { return p == t2::antipode(q); }
}  // namespace ex01
