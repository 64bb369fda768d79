#pragma once
// Exercise 11b: the API you implement in dual.cpp. Do not change this file.
#include <vector>

#include <t2/kernel/point.hpp>

namespace ex11b {

// The input of both functions (chapter 11, sections 2 and 6):
//  - P: distinct proper sites of T² (w != 0, front or back, no two equal as points of T²),
//    at least three; no site on Ω.
//  - F: the Delaunay complex of P, flat: face f is (F[3f], F[3f + 1], F[3f + 2]), three site
//    indices counter-clockwise around the face's Voronoi vertex (a polygon of k >= 4 sites comes
//    as k - 2 triangles of some fan). The faces close up: every side s -> t of a face appears as
//    t -> s in exactly one other face (its neighbour across the Delaunay edge s t).
//
// The Voronoi vertex of a face is exercise 11's vertex: [2A, -B, -C] with the side rule for three
// sites on one side not collinear, else the pole [0, l_x, l_y] of the first consecutive pair
// p -> q of one side (collinear: the pair without the third strictly between its ends).

/// The Voronoi vertices: one per distinct point of T² (faces with the same vertex are merged,
/// section 6), numbered in the order of the first face that has it (the vertex of face 0 is
/// vertex 0, the next new one vertex 1, ...). Exact; any positive multiple is accepted.
std::vector<t2::ExactPoint> voronoi_vertices(const std::vector<t2::Point>& P, const std::vector<long>& F);

/// The Voronoi edges, flat quadruples (a, b, s, t): one per Delaunay edge s t whose two faces
/// have different vertices; s -> t is a side of a face of vertex a, t -> s a side of a face of
/// vertex b (vertex numbers as in voronoi_vertices). (b, a, t, s) is the same edge; any order.
/// No edge between two faces of one vertex: a merged vertex has no edge of length zero.
std::vector<long> voronoi_edges(const std::vector<t2::Point>& P, const std::vector<long>& F);

}  // namespace ex11b
