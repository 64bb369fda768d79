// Hostile: tries to allocate 64 GB.
#include <vector>
#include "classify.hpp"
namespace ex01 {
static bool hog() { std::vector<char> v(64ull << 30, 1); return v[12345] == 1; }
Where where(const t2::Point&) { return hog() ? Where::front : Where::back; }
bool same_point(const t2::Point&, const t2::Point&) { return hog(); }
bool antipodal(const t2::Point&, const t2::Point&) { return hog(); }
}  // namespace ex01
