#pragma once
/// @file constructions.hpp
/// @brief Every construction of the kernel (CGAL's split: new objects computed from old ones),
/// in one include. Exact on `Integer` coordinates (T² needs no division); rounded on `double`
/// coordinates, like CGAL's "exact predicates, inexact constructions" kernel. The predicates
/// are in predicates.hpp.
///
/// - line.hpp: `join` (the line through two points), `meet` (the point of two lines);
/// - midpoint.hpp: the midpoint of two points of T²;
/// - distance.hpp: `squared_distance` (a point of T¹);
/// - affine.hpp: affine and projective maps;
/// - point.hpp: `antipode`, `to_exact`, `to_double`, `normalized`.

#include "t2/kernel/affine.hpp"
#include "t2/kernel/distance.hpp"
#include "t2/kernel/line.hpp"
#include "t2/kernel/midpoint.hpp"
#include "t2/kernel/point.hpp"
