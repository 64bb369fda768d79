#pragma once
/// @file polyhedron.hpp
/// @brief Polyhedra of R³ as face lists (seed 004 §6.1; the type `Polyhedron` is in the kernel,
/// t2/kernel/polyhedron.hpp): Euler's formula and exact certificates of a closed surface and of a
/// convex polyhedron.
///
/// A face list holds one kind of adjacency only (vertices of a face); the others — the faces
/// around a vertex, the faces across the edges of a face — take a search of the whole list.
/// winged_edge.hpp keeps them all in constant space per element.

#include <array>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "t2/kernel/orient3d.hpp"
#include "t2/kernel/polyhedron.hpp"

namespace t2 {

/// An undirected edge (smaller index first).
using Edge3 = std::array<std::uint32_t, 2>;

/// The edges of the faces, each once, sorted.
std::vector<Edge3> edges(const Polyhedron& P);

/// V − E + F, with E the number of distinct edges (2 for a polyhedron of genus 0).
long euler_characteristic(const Polyhedron& P);

/// Checks that the faces form a closed oriented surface: every face has at least three distinct
/// vertices, every directed edge a → b of a face occurs once and its reverse b → a once (in
/// another face), every vertex lies on a face, and the 1-skeleton is connected. Returns an
/// empty string or what is wrong.
std::string validate_surface(const Polyhedron& P);

/// Checks exactly (orient3d) that P is a convex polyhedron with the faces given: every face is
/// planar, turns counter-clockwise seen from outside at each vertex (strictly: no three
/// consecutive vertices collinear), and has every vertex not on it strictly on its inner side.
/// With validate_surface, this certifies the faces are the facets of the hull of the vertices.
/// Returns an empty string or what is wrong.
std::string validate_convex(const Polyhedron& P);

/// True when every point of `points` lies on the inner side of the plane of every face of P,
/// or on it (orient3d ≤ 0 against three consecutive vertices of the face): exact.
bool contains_all(const Polyhedron& P, std::span<const Point3> points);

}  // namespace t2
