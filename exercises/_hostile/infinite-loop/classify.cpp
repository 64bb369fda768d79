// Hostile: never returns.
#include "classify.hpp"
namespace ex01 {
static bool spin() { for (volatile unsigned long i = 0;; i = i + 1) {} return true; }
Where where(const t2::Point&) { spin(); return Where::front; }
bool same_point(const t2::Point&, const t2::Point&) { return spin(); }
bool antipodal(const t2::Point&, const t2::Point&) { return spin(); }
}  // namespace ex01
