// Hostile (issue 29, minor): t2::antipode (brought under the library's name: the exercise's
// headers no longer hold it) on a number type whose name is 8192 characters long. Its symbol
// is then longer than 4096 characters; a reader that cut names there could not demangle it and
// never saw "t2::antipode". The rest is honest, exact arithmetic on big integers: score 0,
// refused by name.
#include "classify.hpp"
namespace t2 {
template <class T>
BasicPoint<T> antipode(const BasicPoint<T>& p) {
  return BasicPoint<T>(-p.w(), -p.x(), -p.y());
}
}  // namespace t2
namespace ex01 {
namespace {
// A tag type whose name is 8192 characters long: "ab" doubled twelve times.
#define T2_CAT(a, b) a##b
#define T2_TWICE(a) T2_CAT(a, a)
#define T2_LONG T2_TWICE(T2_TWICE(T2_TWICE(T2_TWICE(T2_TWICE(T2_TWICE(T2_TWICE(T2_TWICE(T2_TWICE(T2_TWICE(T2_TWICE(T2_TWICE(ab))))))))))))
struct T2_LONG {};
using Tag = T2_LONG;
// A big integer whose type's name holds the tag.
template <class Name>
struct Num : t2::Integer {
  template <class E>
  Num(const E& e) : t2::Integer(e) {}
};
using Long = Num<Tag>;
t2::BasicPoint<Long> wrap(const t2::ExactPoint& p) { return t2::BasicPoint<Long>(p.w(), p.x(), p.y()); }
t2::ExactPoint unwrap(const t2::BasicPoint<Long>& p) { return t2::ExactPoint(p.w(), p.x(), p.y()); }
// p × q = 0 and p · q > 0, exactly.
bool same(const t2::ExactPoint& p, const t2::ExactPoint& q) {
  return p.w() * q.x() == p.x() * q.w() && p.w() * q.y() == p.y() * q.w() && p.x() * q.y() == p.y() * q.x() &&
         sgn(p.w() * q.w() + p.x() * q.x() + p.y() * q.y()) > 0;
}
}  // namespace
Where where(const t2::Point& p) { return p.w() > 0 ? Where::front : p.w() < 0 ? Where::back : Where::infinity; }
bool same_point(const t2::Point& p, const t2::Point& q) { return same(t2::to_exact(p), t2::to_exact(q)); }
bool antipodal(const t2::Point& p, const t2::Point& q) {
  return same(t2::to_exact(p), unwrap(t2::antipode(wrap(t2::to_exact(q)))));
}
}  // namespace ex01
