// Hostile: ends the process with status 0 in the middle of the test.
#include <cstdlib>
#include "classify.hpp"
namespace ex01 {
Where where(const t2::Point&) { std::exit(0); }
bool same_point(const t2::Point&, const t2::Point&) { std::exit(0); }
bool antipodal(const t2::Point&, const t2::Point&) { std::exit(0); }
}  // namespace ex01
