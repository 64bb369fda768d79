#pragma once
// The picture of a command's answer (t2 hull, t2 triangulate, t2 delaunay): a figure rendered in
// the planar model (a disk holding every finite point), the spherical model, or both.

#include <string>
#include <vector>

#include "t2/draw.hpp"
#include "t2/point.hpp"

namespace t2cli {

/// Renders `f` as SVG in the models named by `model` (plane, sphere or both); the planar view is
/// large enough to hold every finite point of `points`.
std::string render_models(const t2::draw::Figure& f, const std::vector<t2::Point>& points, const std::string& model);

}  // namespace t2cli
