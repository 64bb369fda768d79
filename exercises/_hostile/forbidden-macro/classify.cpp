// Forbidden (issues 12 and 29): t2::antipode and t2's point equality, brought under the
// library's names (the exercise's headers no longer hold them) and called behind macros and a
// token paste, which no grep of the source finds; the compiled object still refers to
// t2::antipode: score 0, refused by name.
#include "classify.hpp"
#define CAT(a, b) a##b
#define FLIP(q) t2::CAT(anti, pode)(q)
#define SAME(p, q) operator==(p, q)
namespace t2 {
template <class T>
BasicPoint<T> CAT(anti, pode)(const BasicPoint<T>& p) {
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
bool same_point(const t2::Point& p, const t2::Point& q) { return SAME(p, q); }
bool antipodal(const t2::Point& p, const t2::Point& q) { return SAME(p, FLIP(q)); }
}  // namespace ex01
