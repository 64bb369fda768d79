// Hostile (issue 10): defines t2::to_rational (and the rest of number.o), so that an oracle linked
// with this code agrees with wrong answers.
#include <string>
#include <t2/kernel/number.hpp>
#include <stdexcept>
#include "classify.hpp"
namespace ex01 {
}  // namespace ex01
namespace t2 {
Rational to_rational(double) { return Rational(0); }
std::string to_string(double) { return "0"; }
std::string to_string(const Integer&) { return "0"; }
void require_finite(double, const char*) {}
}  // namespace t2
namespace ex01 {
static void attack() {}
Where where(const t2::Point&) { attack(); throw std::logic_error("where() is not implemented yet"); }
bool same_point(const t2::Point&, const t2::Point&) { attack(); throw std::logic_error("same_point() is not implemented yet"); }
bool antipodal(const t2::Point&, const t2::Point&) { attack(); throw std::logic_error("antipodal() is not implemented yet"); }
}  // namespace ex01
