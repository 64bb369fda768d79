#pragma once
// Exercise NN: the API the student implements in api.cpp.
#include <t2/kernel/point.hpp>

namespace exNN {

/// Specify exactly, including the back side, Ω, antipodes and undefined cases.
bool example(const t2::Point& p);

}  // namespace exNN
