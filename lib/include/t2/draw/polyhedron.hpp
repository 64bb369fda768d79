#pragma once
/// @file polyhedron.hpp
/// @brief Polyhedra of R³ drawn with Cairo: an orthographic view, front faces shaded, visible
/// edges solid and hidden edges dashed.
///
/// **Hidden edges.** For a convex polyhedron seen in parallel projection along the direction d
/// towards the viewer, a face is visible iff its outward normal n has n·d > 0, and an edge is
/// hidden iff both its faces are not visible. (A drawing, in doubles: an edge seen exactly
/// edge-on may go either way, which no picture shows.) Non-convex face lists are drawn with the
/// same rule, which is then only an approximation.

#include <filesystem>
#include <span>
#include <string>

#include "t2/draw/render.hpp"
#include "t2/kernel/polyhedron.hpp"

namespace t2::draw {

/// The camera of a 3-D picture: the viewer's direction (azimuth about the z axis from the x axis,
/// elevation above the xy-plane, in degrees) and the picture's size in pixels.
struct View3 {
  double azimuth = 35;    ///< degrees, counter-clockwise from the x axis
  double elevation = 25;  ///< degrees above the xy-plane
  int size = 360;         ///< width and height in pixels
};

/// The picture of P (and of `points`, small grey dots, e.g. the input of a hull) in format f.
std::string render_polyhedron(const Polyhedron& P, const View3& v, Format f = Format::svg,
                              std::span<const Point3> points = {});

/// Writes render_polyhedron to `path` atomically (the format from the extension); returns true.
bool save_polyhedron(const Polyhedron& P, const View3& v, const std::filesystem::path& path,
                     std::span<const Point3> points = {});

}  // namespace t2::draw
