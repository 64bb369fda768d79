#pragma once
/// @file kernel.hpp
/// @brief The kernel layer (target `t2::kernel`, no Cairo): numbers, the filter and expansions,
/// T¹, points, every primitive, predicates and constructions, and scene files. The algorithms of
/// the course are written against it; `<t2/t2.hpp>` adds drawing and the algorithms themselves.

#include "t2/sign.hpp"
#include "t2/error.hpp"
#include "t2/number.hpp"
#include "t2/filter.hpp"
#include "t2/expansion.hpp"
#include "t2/t1.hpp"
#include "t2/point.hpp"
#include "t2/predicates.hpp"
#include "t2/constructions.hpp"
#include "t2/segment.hpp"
#include "t2/ray.hpp"
#include "t2/vector.hpp"
#include "t2/triangle.hpp"
#include "t2/isorect.hpp"
#include "t2/bbox.hpp"
#include "t2/circle.hpp"
#include "t2/polyhedron.hpp"
#include "t2/io.hpp"
#include "t2/scene.hpp"
#include "t2/scene_colors.hpp"
