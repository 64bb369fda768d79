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
/// With `segments` (an animation of segments: segment i joins P[segments[i][0]] and
/// P[segments[i][1]]), every segment is drawn, the step's chain holds segment indices (a
/// sweep's status, drawn as its segments), and the step's text names segments "s7".
std::string frame_svg(const std::vector<t2::Point>& P, const t2::trace::Step& s,
                      const std::vector<t2::trace::Edge>& segments = {});

}  // namespace t2cli::animate
