#pragma once
/// @file platonic.hpp
/// @brief The five Platonic solids, with exact coordinates (integers), as hulls.
///
/// Tetrahedron, cube and octahedron have integer vertices: alternate corners of the cube, the
/// corners (±1, ±1, ±1), the points ±eᵢ. The icosahedron's vertices (0, ±1, ±φ) and their cyclic
/// permutations involve the golden ratio φ, which no double holds; the library takes the
/// Fibonacci ratio 34/21 ≈ φ instead and scales by 21: (0, ±21, ±34) and cyclic. For any ratio
/// above 1 these twelve points span a convex polyhedron with 20 triangles, 5 at each vertex (the
/// combinatorial icosahedron; its triangles are nearly, not exactly, equilateral). The
/// dodecahedron is its *polar dual*: face n·x = d of the icosahedron gives the vertex n/d,
/// and the poles of the five faces around a vertex v all lie on the plane v·x = 1, so the twelve
/// pentagons are exactly planar (no rounding could promise that for a golden-ratio
/// construction). The poles are scaled by the lcm of the d's to integers.

#include <string_view>
#include <vector>

#include "t2/hull3d/polyhedron.hpp"

namespace t2 {

/// The Platonic solids.
enum class Platonic {
  tetrahedron,   ///< 4 triangles, 3 at a vertex
  cube,          ///< 6 squares, 3 at a vertex
  octahedron,    ///< 8 triangles, 4 at a vertex
  dodecahedron,  ///< 12 pentagons, 3 at a vertex
  icosahedron,   ///< 20 triangles, 5 at a vertex
};

/// All five, in the order of the enumeration.
const std::vector<Platonic>& all_platonic();

/// The name ("dodecahedron").
std::string_view name(Platonic s);

/// The solid with exact integer vertices, its faces computed as the hull's facets.
Polyhedron platonic(Platonic s);

/// The polar dual of a convex polyhedron containing the origin strictly inside, with integer
/// vertices: one vertex per face (the pole n/d, scaled by the lcm of the d's to integers), one
/// face per vertex. Throws `Undefined` if the origin is not strictly inside or the integers
/// would not be exact doubles.
Polyhedron polar_dual(const Polyhedron& P);

}  // namespace t2
