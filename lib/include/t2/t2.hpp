#pragma once
/// @file t2.hpp
/// @brief Everything of the t2 library: include this one header.
///
/// Each header holds one concept; they are listed here in the order the course teaches them.

#include "t2/kernel/sign.hpp"
#include "t2/kernel/error.hpp"
#include "t2/kernel/number.hpp"
#include "t2/kernel/filter.hpp"
#include "t2/kernel/t1.hpp"
#include "t2/kernel/point.hpp"
#include "t2/kernel/orient.hpp"
#include "t2/kernel/line.hpp"
#include "t2/kernel/segment.hpp"
#include "t2/kernel/ray.hpp"
#include "t2/kernel/vector.hpp"
#include "t2/kernel/triangle.hpp"
#include "t2/kernel/isorect.hpp"
#include "t2/kernel/bbox.hpp"
#include "t2/kernel/circle.hpp"
#include "t2/kernel/affine.hpp"
#include "t2/kernel/io.hpp"
#include "t2/draw.hpp"
#include "t2/kernel/scene.hpp"
#include "t2/kernel/polygon.hpp"
#include "t2/kernel/point_in_polygon.hpp"
#include "t2/kernel/closest_point.hpp"
#include "t2/triangulation/ear_clipping.hpp"
#include "t2/kernel/distance.hpp"
#include "t2/kernel/midpoint.hpp"
#include "t2/kernel/lexicographic.hpp"
#include "t2/kernel/angle.hpp"
#include "t2/kernel/incircle.hpp"
