// Forbidden (issue 12): correct answers, by calling the library's t2::antipode and point equality,
// which the exercise asks the student to write; the grader reads the object's symbols: score 0.
#include "classify.hpp"
namespace ex01 {
Where where(const t2::Point& p) { return p.w() > 0 ? Where::front : p.w() < 0 ? Where::back : Where::infinity; }
bool same_point(const t2::Point& p, const t2::Point& q) { return p == q; }
bool antipodal(const t2::Point& p, const t2::Point& q) { return p == t2::antipode(q); }
}  // namespace ex01
