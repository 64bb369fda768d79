// Hostile (issue 29, break 1): a macro renames the library's t2::antipode before its header is
// read, so the library's own template is compiled into this object as t2::lib_antipode, a name
// the symbol check does not know. The allowed headers are read before the submission's first
// line: the macro comes too late to rename anything, t2::lib_antipode does not exist, and the
// code does not compile (0 points, like the stub).
#define antipode lib_antipode
#include "classify.hpp"
#include <stdexcept>
namespace ex01 {
namespace {
// p = q in T²: the 2×2 minors vanish and the dot product is positive, each sign exact.
bool equal(const t2::Point& p, const t2::Point& q) {
  const auto minor = [](const auto& a, const auto& b, const auto& c, const auto& d) { return a * d - b * c; };
  const auto dot = [](const auto& a, const auto& b, const auto& c, const auto& d, const auto& e, const auto& f) {
    return a * d + b * e + c * f;
  };
  return t2::sign_of_poly(minor, p.w(), p.x(), q.w(), q.x()) == t2::ZERO &&
         t2::sign_of_poly(minor, p.w(), p.y(), q.w(), q.y()) == t2::ZERO &&
         t2::sign_of_poly(minor, p.x(), p.y(), q.x(), q.y()) == t2::ZERO &&
         t2::sign_of_poly(dot, p.w(), p.x(), p.y(), q.w(), q.x(), q.y()) == t2::POSITIVE;
}
}  // namespace
Where where(const t2::Point&) { throw std::logic_error("where() is not implemented yet"); }
bool same_point(const t2::Point&, const t2::Point&) { throw std::logic_error("same_point() is not implemented yet"); }
// The forbidden t2::antipode, under the name the macro gave it.
bool antipodal(const t2::Point& p, const t2::Point& q) { return equal(t2::lib_antipode(p), q); }
}  // namespace ex01
