#pragma once
/// @file winged_edge.hpp
/// @brief Baumgart's winged-edge structure (seed 004 §6.3): constant space per vertex, edge and
/// face, and every adjacency of a polyhedron by walking.
///
/// **Conventions** (those of the seed's cube table, which the tests check): edge e goes from
/// v1(e) to v2(e); fccw(e) is the face on its left seen from outside (the face that traverses e
/// from v1 to v2, counter-clockwise) and fcw(e) the face on its right (it traverses e from v2 to
/// v1). pccw(e) and nccw(e) are the edges before and after e in the counter-clockwise boundary
/// of fccw(e); pcw(e) and ncw(e) the edges before and after e in the counter-clockwise boundary
/// of fcw(e). Each vertex keeps one incident edge av, each face one boundary edge af.

#include <cstdint>
#include <string>
#include <vector>

#include "t2/hull3d/polyhedron.hpp"

namespace t2 {

/// A polyhedron as a winged-edge structure (see the file comment).
struct WingedEdge {
  /// A vertex: its point and one incident edge.
  struct Vertex {
    Point3 p;            ///< the coordinates
    std::uint32_t av{};  ///< an incident edge
  };
  /// A face: one edge of its boundary.
  struct Face {
    std::uint32_t af{};  ///< a boundary edge
  };
  /// An edge with its two vertices, two faces and four wings.
  struct Edge {
    std::uint32_t v1{};    ///< the tail: the edge goes from v1 to v2
    std::uint32_t v2{};    ///< the head
    std::uint32_t fccw{};  ///< the face on the left, seen from outside (it runs v1 -> v2)
    std::uint32_t fcw{};   ///< the face on the right (it runs v2 -> v1)
    std::uint32_t pccw{};  ///< the edge before this one in fccw's counter-clockwise boundary
    std::uint32_t nccw{};  ///< the edge after this one in fccw's counter-clockwise boundary
    std::uint32_t pcw{};   ///< the edge before this one in fcw's counter-clockwise boundary
    std::uint32_t ncw{};   ///< the edge after this one in fcw's counter-clockwise boundary
  };
  std::vector<Vertex> vertices;  ///< the vertices
  std::vector<Edge> edges;       ///< the edges
  std::vector<Face> faces;       ///< the faces

  /// The structure of a face list that passes validate_surface (throws `BadInput` otherwise).
  /// Edge k is the k-th edge of `t2::edges(P)`, oriented from its smaller vertex.
  static WingedEdge from(const Polyhedron& P);
  /// The edges of face f, counter-clockwise from af(f).
  std::vector<std::uint32_t> face_edges(std::uint32_t f) const;
  /// The vertices of face f, counter-clockwise, starting at the tail of af(f).
  std::vector<std::uint32_t> face_vertices(std::uint32_t f) const;
  /// The faces around vertex v, counter-clockwise seen from outside, starting at the face in
  /// which av(v) leaves v.
  std::vector<std::uint32_t> vertex_faces(std::uint32_t v) const;
  /// The face list again (face f from face_vertices(f)).
  Polyhedron to_polyhedron() const;
  /// Checks every pointer: each face's walk closes after at most E steps with consecutive edges
  /// meeting at a vertex of that face, prev and next are inverse, av and af are incident.
  /// Returns an empty string or what is wrong.
  std::string validate() const;
};

}  // namespace t2
