#pragma once
/// @file subdivision.hpp
/// @brief A polygonal subdivision of T² (seed 000 §5.7): faces given as polygons, one half-edge
/// structure over them, and the complement of the faces as one more region, `outside`.
///
/// **The half-edges.** Face f has the vertices v₀ … v_{n−1} (indices into `points()`, equal
/// points merged) and the half-edges h = first(f) + k, k < n, from v_k to v_{k+1}; the face lies
/// to the left of each (the positive side of the polygon, point_in_polygon.hpp). `twin(h)` is
/// the half-edge of another face from v_{k+1} to v_k, or `none` for a *boundary* edge, whose
/// other side is the complement. This is chapter 09's DCEL without its edge records: next and
/// prev are index arithmetic inside a face, and the corners around a vertex are listed once
/// (`corners(v)`), so a walk never searches.
///
/// **What the constructor checks** (a violation throws `MapError` naming the face): every face
/// is a simple polygon of T² (polygon.hpp's `is_simple`); no directed edge is given twice (two
/// faces on the same side of an edge overlap); and at every vertex no face's corner holds the
/// first edge of another face's corner (faces overlapping at a vertex). Not detected (that
/// would be the O(e²) segment test): faces that overlap without sharing a vertex, and a vertex
/// of one face inside an edge of another (a T-junction), where `walk` and `locate_brute` may
/// name the point differently (an edge of one face, a vertex of the other). The check of the
/// corners costs O(d²) at a vertex of degree d.

#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "t2/kernel/error.hpp"
#include "t2/kernel/point.hpp"
#include "t2/kernel/polygon.hpp"

namespace t2 {

/// A map that is not a subdivision: `face()` is the offending face.
class MapError : public BadInput {
 public:
  /// @param face the 0-based index of the face at fault
  /// @param what what is wrong
  MapError(std::size_t face, const std::string& what) : BadInput(what), face_(face) {}
  /// The 0-based index of the face at fault.
  std::size_t face() const { return face_; }

 private:
  std::size_t face_;
};

/// True when the direction from v toward d lies strictly inside the corner u → v → w of a face
/// to the left of both edges: for a convex corner (orient(u, v, w) > 0) d must be left of both
/// u ∨ v and v ∨ w; for a reflex one, left of either; for a straight one (orient 0: w goes on
/// past v, as a simple polygon has no spikes), left of u ∨ v. The arc from v to d lies on one
/// side of each great circle through v, so the three exact signs decide. Needs d ≠ ±v.
bool in_corner(const Point& u, const Point& v, const Point& w, const Point& d);

/// A subdivision of T² into polygonal faces (see the file comment).
class Subdivision {
 public:
  using Index = std::uint32_t;                 ///< vertex, face and half-edge indices
  static constexpr Index none = 0xFFFFFFFFu;   ///< no twin (a boundary edge)
  static constexpr Index outside = 0xFFFFFFFFu;  ///< the face index of the complement

  /// A corner: face f at its vertex k (the half-edge first(f) + k leaves the vertex).
  struct Corner {
    Index face = 0;  ///< the face
    Index k = 0;     ///< the slot of the vertex in the face
  };

  /// The subdivision whose faces are `faces`, each a polygon of T² (equal points merged
  /// exactly). Throws `MapError` (see the file comment).
  explicit Subdivision(std::span<const Polygon> faces);
  /// The subdivision of `points` whose faces are index cycles into them (no two indices of
  /// the list naming equal points). Throws `MapError`.
  Subdivision(std::vector<Point> points, const std::vector<std::vector<Index>>& faces);

  /// The distinct vertices.
  const std::vector<Point>& points() const { return points_; }
  /// Number of faces.
  std::size_t faces() const { return first_.size() - 1; }
  /// Number of vertices of face f.
  std::size_t size(Index f) const { return first_[f + 1] - first_[f]; }
  //> half-edges
  /// The first half-edge of face f.
  Index first(Index f) const { return first_[f]; }
  /// The face to the left of half-edge h.
  Index face(Index h) const { return face_[h]; }
  /// The slot of half-edge h in its face.
  Index slot(Index h) const { return h - first_[face_[h]]; }
  /// The origin vertex of h.
  Index org(Index h) const { return org_[h]; }
  /// The next half-edge around the face of h.
  Index next(Index h) const {
    return h + 1 == first_[face_[h] + 1] ? first_[face_[h]] : h + 1;
  }
  /// The previous half-edge around the face of h.
  Index prev(Index h) const {
    return h == first_[face_[h]] ? first_[face_[h] + 1] - 1 : h - 1;
  }
  /// The destination vertex of h.
  Index dest(Index h) const { return org_[next(h)]; }
  /// The half-edge of the face across h, from dest(h) to org(h), or `none` (boundary).
  Index twin(Index h) const { return twin_[h]; }
  //< half-edges
  /// Number of half-edges.
  std::size_t half_edges() const { return org_.size(); }
  /// The corners at vertex v (one per face that has v).
  std::span<const Corner> corners(Index v) const {
    return {corner_.data() + corner_first_[v], corner_.data() + corner_first_[v + 1]};
  }
  /// The boundary half-edges (no twin): the edges of the complement, `outside`.
  const std::vector<Index>& boundary() const { return boundary_; }
  /// Whether face f is a convex triangle (three vertices, Δ > 0: the small triangle of T², not
  /// its complement), the faces on which the walks take their short steps (walk.hpp); decided
  /// once, by the exact `orient`, when the map is made.
  bool convex_triangle(Index f) const { return convex_[f] != 0; }

 private:
  void build(const std::vector<std::vector<Index>>& faces);
  void check_corners() const;
  std::vector<Point> points_;
  std::vector<Index> first_{0}, face_, org_, twin_, boundary_;
  std::vector<Index> corner_first_;
  std::vector<Corner> corner_;
  std::vector<std::uint8_t> convex_;  // per face: 1 for a convex triangle
};

}  // namespace t2
