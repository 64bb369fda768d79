#pragma once
/// @file overlay.hpp
/// @brief Putting constructed geometry into a step's overlay (step.hpp): kernel objects into
/// the `t2::Scene` that a player draws over the step's picture.
///
/// The overlay holds the kernel's own types, so a circle keeps its exact centre and boundary
/// point and a player draws exactly what the algorithm constructed. One function a kind.

#include <string>

#include "t2/kernel/circle.hpp"
#include "t2/kernel/point.hpp"
#include "t2/kernel/scene.hpp"

namespace t2::trace {

/// A point of an overlay (no line of a file, no label, no style of its own).
inline ScenePoint overlay_point(const Point& p) { return ScenePoint{p, 0, {}, {}}; }

/// Adds the circle c (its centre and boundary point) to the overlay, labelled `label`.
inline void add_circle(Scene& overlay, const Circle& c, const std::string& label = "") {
  SceneCircle s{overlay_point(c.center()), overlay_point(c.boundary_point()), 0, {}};
  if (!label.empty()) s.style.label = label;
  overlay.circles.push_back(std::move(s));
}

/// Adds the point p (a constructed point: a Voronoi vertex, an intersection), labelled `label`.
inline void add_point(Scene& overlay, const Point& p, const std::string& label = "") {
  ScenePoint s = overlay_point(p);
  if (!label.empty()) s.style.label = label;
  overlay.points.push_back(std::move(s));
}

/// Adds the segment a b (a sweep line's visible part, a split of a kd-tree cell).
inline void add_segment(Scene& overlay, const Point& a, const Point& b) {
  overlay.segments.push_back(SceneSegment{overlay_point(a), overlay_point(b), 0, {}});
}

/// Adds the line through a and b, oriented from a to b (a sweep line, a bisector).
inline void add_line(Scene& overlay, const Point& a, const Point& b) {
  overlay.lines.push_back(SceneLine{overlay_point(a), overlay_point(b), 0, {}});
}

}  // namespace t2::trace
