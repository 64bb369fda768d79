#pragma once
/// @file quadedge.hpp
/// @brief Guibas and Stolfi's quad-edge structure ("Primitives for the manipulation of general
/// subdivisions and the computation of Voronoi diagrams", ACM TOG 4(2), 1985; seed 003,
/// §4.3.3.1) on flat arrays: a subdivision of the plane and its dual in one structure, built by
/// two operations, `make_edge` and `splice`.
///
/// **Quarter-edges.** Every undirected edge of the subdivision is one *quad*: four quarter-edges
/// numbered 4q, 4q + 1, 4q + 2, 4q + 3. Quarter-edge 4q + r is the edge turned r quarter turns
/// counter-clockwise: r = 0 the edge in one direction, r = 2 the same edge reversed, r = 1 and
/// r = 3 its dual edge (from the face on the right of 4q to the face on its left, and back).
/// So the edge algebra is index arithmetic, no pointer is stored for it:
///
///     rot(e) = 4q + (r + 1) mod 4     sym(e) = rot(rot(e)) = e xor 2     rot⁻¹(e) = rot³(e)
///
/// The only stored topology is `onext(e)`, the next quarter-edge counter-clockwise around the
/// origin of e (for a dual quarter-edge: around its origin face), one 32-bit index per
/// quarter-edge; every other walk is a composition (Guibas and Stolfi, §2.5):
///
///     oprev(e) = rot(onext(rot(e)))         (clockwise around the origin)
///     lnext(e) = rot(onext(rot⁻¹(e)))       (counter-clockwise around the left face)
///     lprev(e) = sym(onext(e))              rnext(e) = rot⁻¹(onext(rot(e)))
///     rprev(e) = onext(sym(e))              dnext(e) = sym(onext(sym(e)))
///
/// The primal quarter-edges (r = 0, 2) carry their origin vertex, `org(e)`, in a second array
/// indexed by e / 2; dest(e) = org(sym(e)). The dual ones carry nothing here (a face would).
///
/// **Splice.** `splice(a, b)` exchanges onext(a) with onext(b), and onext(α) with onext(β) for
/// α = rot(onext(a)), β = rot(onext(b)). If a and b have different origins it joins their rings
/// into one (the origins become one vertex) and splits the face they share; if they have the same
/// origin it splits that ring in two and joins the two faces. It is its own inverse. With
/// `make_edge` (one edge alone: its own ring at each end, one face on both sides) it builds every
/// subdivision, and `connect` and `delete_edge` are two splices each.
///
/// **Memory.** 16 bytes of onext and 8 of origins per edge, plus a free list of deleted quads
/// that `make_edge` reuses: a triangulation of n points has about 3n edges, 72 bytes a point.

#include <cstdint>
#include <utility>
#include <vector>

namespace t2 {

/// A quad-edge subdivision on flat arrays (see the file comment).
class QuadEdge {
 public:
  using Edge = std::uint32_t;                       ///< a quarter-edge 4q + r
  using Vertex = std::uint32_t;                     ///< the data of a primal quarter-edge
  static constexpr Vertex deleted = 0xFFFFFFFFu;    ///< the origin of a deleted edge

  /// An empty subdivision with room for `edges` edges.
  explicit QuadEdge(std::size_t edges = 0) {
    next_.reserve(4 * edges);
    org_.reserve(2 * edges);
  }

  //> quadedge-algebra
  /// The quarter-edge turned a quarter turn counter-clockwise (the dual, right to left
  /// face).
  static Edge rot(Edge e) { return (e & ~3u) | ((e + 1) & 3u); }
  /// The same edge, reversed.
  static Edge sym(Edge e) { return e ^ 2u; }
  /// The quarter-edge turned a quarter turn clockwise: rot(rot(rot(e))).
  static Edge rot_inv(Edge e) { return (e & ~3u) | ((e + 3) & 3u); }
  /// The next edge counter-clockwise around the origin of e (stored).
  Edge onext(Edge e) const { return next_[e]; }
  /// The next edge clockwise around the origin of e.
  Edge oprev(Edge e) const { return rot(next_[rot(e)]); }
  /// The next edge counter-clockwise around the face on the left of e.
  Edge lnext(Edge e) const { return rot(next_[rot_inv(e)]); }
  /// The previous edge around the face on the left of e.
  Edge lprev(Edge e) const { return sym(next_[e]); }
  /// The next edge counter-clockwise around the face on the right of e.
  Edge rnext(Edge e) const { return rot_inv(next_[rot(e)]); }
  /// The previous edge around the face on the right of e (the next one clockwise).
  Edge rprev(Edge e) const { return next_[sym(e)]; }
  /// The next edge counter-clockwise around the destination of e.
  Edge dnext(Edge e) const { return sym(next_[sym(e)]); }
  /// The origin vertex of the primal quarter-edge e.
  Vertex org(Edge e) const { return org_[e >> 1]; }
  /// The destination vertex of the primal quarter-edge e.
  Vertex dest(Edge e) const { return org_[sym(e) >> 1]; }
  //< quadedge-algebra

  /// Number of quads ever made (deleted ones included): quarter-edges are below 4·quads().
  std::size_t quads() const { return next_.size() / 4; }
  /// True when the quad of e has been deleted (and not reused).
  bool is_deleted(Edge e) const { return org_[(e & ~3u) >> 1] == deleted; }

  //> quadedge-operations
  /// A new edge from a to b, alone: each end is its own ring, one face on both sides.
  /// Returns its quarter-edge 4q from a to b.
  Edge make_edge(Vertex a, Vertex b) {
    Edge e;
    if (free_ != none) {
      e = free_;
      free_ = next_[e];
    } else {
      e = static_cast<Edge>(next_.size());
      next_.resize(next_.size() + 4);
      org_.resize(org_.size() + 2);
    }
    next_[e] = e;                // the primal edge: a ring of one at each end
    next_[e + 2] = e + 2;
    next_[e + 1] = e + 3;        // the dual edge: one face on both sides, so its two
    next_[e + 3] = e + 1;        // quarter-edges leave the same face, each after the other
    org_[e >> 1] = a;
    org_[(e >> 1) + 1] = b;
    return e;
  }
  /// Joins or separates the rings of a and b, and the rings of their left faces.
  void splice(Edge a, Edge b) {
    const Edge alpha = rot(next_[a]), beta = rot(next_[b]);
    std::swap(next_[a], next_[b]);
    std::swap(next_[alpha], next_[beta]);
  }
  /// A new edge from dest(a) to org(b), added inside the face on the left of a and b (which
  /// must be the same face), after a around the face; returns it.
  Edge connect(Edge a, Edge b) {
    const Edge e = make_edge(dest(a), org(b));
    splice(e, lnext(a));
    splice(sym(e), b);
    return e;
  }
  /// Removes edge e from the subdivision (its two faces become one) and frees its quad.
  void delete_edge(Edge e) {
    splice(e, oprev(e));
    splice(sym(e), oprev(sym(e)));
    e &= ~3u;
    org_[e >> 1] = org_[(e >> 1) + 1] = deleted;
    next_[e] = free_;
    free_ = e;
  }
  //< quadedge-operations

 private:
  static constexpr Edge none = 0xFFFFFFFFu;
  std::vector<Edge> next_;   // onext of every quarter-edge
  std::vector<Vertex> org_;  // the origin of the primal quarter-edges 4q and 4q + 2, at 2q, 2q + 1
  Edge free_ = none;         // the first deleted quad; next_ of its quarter-edge 0 links the rest
};

}  // namespace t2
