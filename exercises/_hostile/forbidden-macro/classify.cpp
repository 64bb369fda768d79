// Forbidden (issue 12): the same library calls hidden behind macros and a token paste, which no
// grep of the source finds; the compiled object still refers to t2::antipode: score 0.
#include "classify.hpp"
#define CAT(a, b) a##b
#define FLIP(q) t2::CAT(anti, pode)(q)
#define SAME(p, q) operator==(p, q)
namespace ex01 {
Where where(const t2::Point& p) { return p.w() > 0 ? Where::front : p.w() < 0 ? Where::back : Where::infinity; }
bool same_point(const t2::Point& p, const t2::Point& q) { return SAME(p, q); }
bool antipodal(const t2::Point& p, const t2::Point& q) { return SAME(p, FLIP(q)); }
}  // namespace ex01
