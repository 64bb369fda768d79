#pragma once
// Exercise 14b: the API you implement in locate.cpp. Do not change this file.
#include <array>
#include <vector>

#include <t2/kernel/point.hpp>

namespace ex14b {

/// A face of the map: three indices into the points, counter-clockwise (Δ(a, b, c) > 0).
using Triangle = std::array<int, 3>;

/// Where a query lies, as `t2 locate` prints it: `face F`, `edge F K`, `vertex F K`, `outside`.
struct Location {
  /// What the query hits.
  enum class Kind {
    face,    ///< strictly inside face `face`
    edge,    ///< inside the edge of `face` from its vertex k to its vertex k + 1 (mod 3)
    vertex,  ///< equal to vertex k of `face`
    outside  ///< in no closed face (the complement of the map)
  } kind = Kind::outside;  ///< what the query hits
  int face = -1;           ///< the face (−1 for `outside`)
  int k = 0;               ///< the slot 0, 1, 2 of the edge or vertex in `face` (0 otherwise)
  /// Same kind, face and slot.
  friend bool operator==(const Location&, const Location&) = default;
};

/// For each query Q[i], its location in the map (P, T) of T²: the points P (no two equal) and
/// the faces T, triangles of P with Δ(a, b, c) > 0 whose interiors are disjoint and which meet,
/// if at all, in a common vertex or a common edge (traversed in opposite directions). A query
/// on an edge or a vertex is answered with the face of least index that has it, and its slot
/// there. Faces may lie on the back side or cross Ω; the map may leave part of T² uncovered, in
/// several pieces (holes). Points of P that no face uses are not vertices of the map.
///
/// T holds up to 10⁵ faces and Q up to 10⁵ queries, in no particular order (shuffled):
/// a walk from the last answer crosses about √f faces a query and stops at every hole. Locate
/// them all in O((f + m) log(f + m)): sweep (chapter 13) the half-great-circles from a pole of
/// T², or another logarithmic method; testing every face is far too slow.
std::vector<Location> locate_all(const std::vector<t2::Point>& P, const std::vector<Triangle>& T,
                                 const std::vector<t2::Point>& Q);

}  // namespace ex14b
