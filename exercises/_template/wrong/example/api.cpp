// Wrong on purpose: say which mistake this solution makes.
#include "api.hpp"

namespace exNN {

bool example(const t2::Point& p) { return p.w() <= 0; }

}  // namespace exNN
