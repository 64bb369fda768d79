// Hostile (issue 29, minor): a forbidden name that carries an ABI tag, as every function
// returning a std::string does. Its demangled name ends in "[abi:cxx11]", which a parser of
// demangled names never matched with t2::collinear. Exact and right, but under a forbidden
// name: score 0, refused by name.
#include "classify.hpp"
namespace t2 {
[[gnu::abi_tag("cxx11")]] bool collinear(const ExactPoint& p, const ExactPoint& q) {
  return p.w() * q.x() == p.x() * q.w() && p.w() * q.y() == p.y() * q.w() && p.x() * q.y() == p.y() * q.x();
}
}  // namespace t2
namespace ex01 {
namespace {
int dot_sign(const t2::ExactPoint& p, const t2::ExactPoint& q) { return sgn(p.w() * q.w() + p.x() * q.x() + p.y() * q.y()); }
}  // namespace
Where where(const t2::Point& p) { return p.w() > 0 ? Where::front : p.w() < 0 ? Where::back : Where::infinity; }
bool same_point(const t2::Point& p, const t2::Point& q) {
  const auto a = t2::to_exact(p), b = t2::to_exact(q);
  return t2::collinear(a, b) && dot_sign(a, b) > 0;
}
bool antipodal(const t2::Point& p, const t2::Point& q) {
  const auto a = t2::to_exact(p), b = t2::to_exact(q);
  return t2::collinear(a, b) && dot_sign(a, b) < 0;
}
}  // namespace ex01
