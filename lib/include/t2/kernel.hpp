#pragma once
/// @file kernel.hpp
/// @brief The kernel layer (target `t2::kernel`, no Cairo): numbers, the filter and expansions,
/// T¹, points, every primitive, predicates and constructions, and scene files. The algorithms of
/// the course are written against it; `<t2/t2.hpp>` adds drawing and the algorithms themselves.

#include "t2/kernel/sign.hpp"
#include "t2/kernel/error.hpp"
#include "t2/kernel/number.hpp"
#include "t2/kernel/filter.hpp"
#include "t2/kernel/expansion.hpp"
#include "t2/kernel/t1.hpp"
#include "t2/kernel/point.hpp"
#include "t2/kernel/predicates.hpp"
#include "t2/kernel/chart.hpp"
#include "t2/kernel/constructions.hpp"
#include "t2/kernel/segment.hpp"
#include "t2/kernel/ray.hpp"
#include "t2/kernel/vector.hpp"
#include "t2/kernel/triangle.hpp"
#include "t2/kernel/isorect.hpp"
#include "t2/kernel/bbox.hpp"
#include "t2/kernel/circle.hpp"
#include "t2/kernel/polyhedron.hpp"
#include "t2/kernel/io.hpp"
#include "t2/kernel/scene.hpp"
#include "t2/kernel/scene_colors.hpp"
