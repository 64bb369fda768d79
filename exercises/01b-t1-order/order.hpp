#pragma once
// Exercise 01b: the API you implement in order.cpp. Do not change this file.
#include <t2/kernel/sign.hpp>

namespace ex01b {

/// Compares two points a = [aw, ax] and b = [bw, bx] of T¹ (pairs of finite doubles, never
/// [0, 0], equal when one is a positive multiple of the other: chapter 01, section 2).
/// The order goes once around the circle model counter-clockwise, starting at the front zero
/// [1, 0]: by the angle of the vector (w, x), measured from (1, 0), in [0, 2π).
/// NEGATIVE when a comes before b, ZERO when a = b, POSITIVE when a comes after b.
/// Exact for every finite double (no epsilon, no angle computed in floating point).
t2::Sign compare(double aw, double ax, double bw, double bx);

}  // namespace ex01b
