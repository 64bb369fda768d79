#pragma once
/// @file predicates.hpp
/// @brief Every predicate of the kernel (CGAL's split: questions with a discrete answer, exact
/// for every finite input), in one include. The constructions are in constructions.hpp.
///
/// - orient.hpp: `orient`, `collinear` (Δ of three points of T²);
/// - incircle.hpp: `in_circle`, `in_disk`;
/// - orient3d.hpp: `orient3d` (four points of R³, Volume6);
/// - line.hpp: `side` (of a point relative to a line);
/// - point.hpp: `==` (equality in T²), `side_of`;
/// - distance.hpp: `compare_distance`, `compare_distance_values` (§4.3.1);
/// - lexicographic.hpp: `compare_lexicographic`, `compare_xy`, `compare_along_line` (§4.3.3);
/// - angle.hpp: the comparisons of directions.
/// - sign_sqrt.hpp: `sign_of_root_sum` (the sign of A + B√C for polynomials A, B, C),
///   `sign_of_root_difference`.
///
/// On `double` coordinates each has a fast path of plain double arithmetic with an error bound
/// proven in its header, and exact stages (expansion.hpp, then GMP where expansions cannot go).

#include "t2/kernel/angle.hpp"
#include "t2/kernel/distance.hpp"
#include "t2/kernel/incircle.hpp"
#include "t2/kernel/lexicographic.hpp"
#include "t2/kernel/line.hpp"
#include "t2/kernel/orient.hpp"
#include "t2/kernel/orient3d.hpp"
#include "t2/kernel/point.hpp"
#include "t2/kernel/sign_sqrt.hpp"
