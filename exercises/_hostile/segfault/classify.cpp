// Hostile: dereferences a null pointer.
#include "classify.hpp"
namespace ex01 {
static bool crash() { volatile int* volatile p = nullptr; return *p == 1; }
Where where(const t2::Point&) { crash(); return Where::front; }
bool same_point(const t2::Point&, const t2::Point&) { return crash(); }
bool antipodal(const t2::Point&, const t2::Point&) { return crash(); }
}  // namespace ex01
