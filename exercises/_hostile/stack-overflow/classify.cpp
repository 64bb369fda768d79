// Hostile: runaway recursion.
#include "classify.hpp"
namespace ex01 {
static int deep(volatile int n) { volatile char pad[256]; pad[0] = static_cast<char>(n); return deep(n + 1) + pad[0]; }
Where where(const t2::Point&) { return deep(0) ? Where::front : Where::back; }
bool same_point(const t2::Point&, const t2::Point&) { return deep(0) > 0; }
bool antipodal(const t2::Point&, const t2::Point&) { return deep(0) > 0; }
}  // namespace ex01
