#pragma once
/// @file hull.hpp
/// @brief Convex hulls in T² (chapter 06): `t2::convex_hull` and its algorithms; and the
/// calipers chapter (07): polygon hulls, antipodal pairs, diameter, width, convex layers and the
/// kernel of a polygon.

#include "t2/hull/calipers.hpp"
#include "t2/hull/convex_hull.hpp"
#include "t2/hull/diameter.hpp"
#include "t2/hull/layers.hpp"
#include "t2/hull/melkman.hpp"
#include "t2/hull/polygon_kernel.hpp"
