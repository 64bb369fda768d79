#pragma once
/// @file t2.hpp
/// @brief Everything of the t2 library: include this one header.
///
/// Each header holds one concept; they are listed here in the order the course teaches them.

#include "t2/sign.hpp"
#include "t2/error.hpp"
#include "t2/number.hpp"
#include "t2/filter.hpp"
#include "t2/t1.hpp"
#include "t2/point.hpp"
#include "t2/orient.hpp"
#include "t2/line.hpp"
#include "t2/segment.hpp"
#include "t2/ray.hpp"
#include "t2/vector.hpp"
#include "t2/triangle.hpp"
#include "t2/isorect.hpp"
#include "t2/bbox.hpp"
#include "t2/circle.hpp"
#include "t2/affine.hpp"
#include "t2/io.hpp"
#include "t2/draw.hpp"
#include "t2/scene.hpp"
#include "t2/polygon.hpp"
#include "t2/point_in_polygon.hpp"
#include "t2/closest_point.hpp"
#include "t2/ear_clipping.hpp"
#include "t2/distance.hpp"
#include "t2/midpoint.hpp"
#include "t2/lexicographic.hpp"
#include "t2/angle.hpp"
#include "t2/incircle.hpp"
