#pragma once
/// @file polyhedron.hpp
/// @brief A polyhedron of R³ as a face list (seed 004 §6.1): the vertices, and each face as the
/// cycle of its vertex indices, counter-clockwise seen from outside. The type only, in the
/// kernel, so that drawing can take one without the algorithms; Euler's formula and the exact
/// certificates of a surface are in t2/hull3d/polyhedron.hpp.

#include <cstdint>
#include <vector>

#include "t2/kernel/orient3d.hpp"

namespace t2 {

/// A polyhedron as a face list: `faces[f]` lists indices into `vertices`, counter-clockwise
/// seen from outside (so the outward normal is (v₁ − v₀) × (v₂ − v₀) for a convex face).
struct Polyhedron {
  std::vector<Point3> vertices;                   ///< the vertices
  std::vector<std::vector<std::uint32_t>> faces;  ///< each face, counter-clockwise from outside
};

}  // namespace t2
