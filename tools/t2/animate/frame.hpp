#pragma once
// The picture of one recorded step (t2/trace/step.hpp) for `t2 animate`: the input points, the
// triangles so far, the chain (stack or hull so far), and what the step highlights, in the
// planar and the spherical model side by side, drawn by the library (t2::draw).
#include <string>
#include <vector>

#include "t2/kernel/point.hpp"
#include "t2/trace/step.hpp"

namespace t2cli::animate {

/// The SVG element (no XML declaration) showing step `s` of an animation of the points P.
std::string frame_svg(const std::vector<t2::Point>& P, const t2::trace::Step& s);

}  // namespace t2cli::animate
