#pragma once
// Exercise 01: the API you implement in classify.cpp. Do not change this file.
#include <t2/kernel/point_type.hpp>

namespace ex01 {

/// Where a point of T² lies.
enum class Where { front, back, infinity };

/// front when w > 0, back when w < 0, infinity when w = 0 (the point is on Ω).
Where where(const t2::Point& p);

/// True when p and q are the same point of T²: q = αp for some α > 0. Must be exact for every
/// finite double (no epsilon, no division).
bool same_point(const t2::Point& p, const t2::Point& q);

/// True when q is the antipode ¬p of p (q = αp for some α < 0). Exact, like same_point.
bool antipodal(const t2::Point& p, const t2::Point& q);

}  // namespace ex01
