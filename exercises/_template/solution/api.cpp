// Exercise NN, reference solution.
#include "api.hpp"

namespace exNN {

bool example(const t2::Point& p) { return p.w() < 0; }

}  // namespace exNN
