// Hostile (issue 10): ends with an exit status in 129..192 that depends on hidden data (here on
// the point it was given), hoping the report shows it (a status that looks like a signal).
#include <unistd.h>
#include <t2/kernel/point.hpp>
#include <stdexcept>
#include "classify.hpp"
namespace ex01 {

static void leak(const t2::Point& p) { _exit(129 + (static_cast<int>(p.x()) & 63)); }
Where where(const t2::Point& p) { leak(p); throw std::logic_error("where() is not implemented yet"); }
bool same_point(const t2::Point& p, const t2::Point&) { leak(p); throw std::logic_error("same_point() is not implemented yet"); }
bool antipodal(const t2::Point& p, const t2::Point&) { leak(p); throw std::logic_error("antipodal() is not implemented yet"); }
}  // namespace ex01
