#pragma once
/// @file hull3d.hpp
/// @brief Part II, chapter 08: polyhedra (face lists, winged edge), the Platonic solids, the
/// 3-D convex hull (gift wrapping, incremental) and the lifting map.

#include "t2/hull3d/convex_hull_3d.hpp"
#include "t2/hull3d/degenerate.hpp"
#include "t2/hull3d/facets.hpp"
#include "t2/hull3d/lift.hpp"
#include "t2/hull3d/platonic.hpp"
#include "t2/hull3d/polyhedron.hpp"
#include "t2/hull3d/winged_edge.hpp"
