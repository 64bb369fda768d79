// Hostile: a syntax error.
#include "classify.hpp"
namespace ex01 {
Where where(const t2::Point& p) { return p.w() > 0 ? Where::front : Where::back }
}
