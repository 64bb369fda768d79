#pragma once
// Exercise 05b: the API you implement in crossing.cpp. Do not change this file.
#include <t2/kernel/point.hpp>

namespace ex05b {

/// The point where the segments ab and cd of T² meet (chapter 02: the segment ab is the set of
/// points αa + βb, α, β ≥ 0), exactly, as a point with integer coordinates. The caller
/// guarantees a ≠ ±b and c ≠ ±d. Throws t2::Undefined when the segments do not meet, and when
/// all four points lie on one line (then they share a piece of that line, one point, or nothing:
/// not this exercise). A common endpoint of two segments on different lines is their crossing.
t2::ExactPoint crossing(const t2::Point& a, const t2::Point& b, const t2::Point& c, const t2::Point& d);

}  // namespace ex05b
