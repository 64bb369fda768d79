// Hostile: prints forever.
#include <cstdio>
#include "classify.hpp"
namespace ex01 {
static bool shout() { for (;;) std::printf("aaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaa\n"); }
Where where(const t2::Point&) { return shout() ? Where::front : Where::back; }
bool same_point(const t2::Point&, const t2::Point&) { return shout(); }
bool antipodal(const t2::Point&, const t2::Point&) { return shout(); }
}  // namespace ex01
