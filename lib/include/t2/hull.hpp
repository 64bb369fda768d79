#pragma once
/// @file hull.hpp
/// @brief Convex hulls in T² (chapter 06): `t2::convex_hull` and its algorithms.

#include "t2/hull/convex_hull.hpp"
