#pragma once
/// @file sites.hpp
/// @brief The candidate pairs of the proximity problems of T² (chapter 12): the sites split by
/// side, equal sites merged, the Delaunay edges of each side, and each side's extreme sites.
///
/// **Why these candidates suffice** (the proofs the algorithms cite). Distances as in
/// pair_distance.hpp. The front triangles of the T² Delaunay triangulation are the planar
/// Delaunay triangulation of the front sites F (delaunay_t2.hpp, (1)), the back ones that of
/// the drawn back sites B̄; this file builds those two directly (`delaunay`), because the
/// whole-sphere structure throws `Undefined` for some sites on Ω (an empty side) and drops
/// the faces beyond a hull, where the proximity answers are still defined.
///  1. *Gabriel.* Let a, b be distinct sites on one side such that no third site c has
///     d(a, c) < d(a, b) and d(b, c) < d(a, b). Then ab is an edge of the planar Delaunay
///     triangulation of that side, whatever the triangulation does with cocircular sites.
///     Proof: a site c of the side in the closed disk with diameter ab sees ab at an angle of at
///     least 90°, so |AB|² ≥ |AC|² + |BC|² and both |AC|, |BC| are strictly below |AB|: there
///     is none. Sites on Ω or on the other side are at +∞ or beyond from any point of the side.
///     So the midpoint m of ab is strictly nearer to a and b than to any other site, and so are
///     the points of the bisector near m: the Voronoi cells of a and b share an edge of positive
///     length, whose dual ab is in every triangulation of the Delaunay complex.
///  2. *Extremes.* For a front site a and a back site b, d(a, b) is beyond infinity and is the
///     smaller the larger |A − B̄| (B̄ the drawn position of b). If (a, b) maximizes |A − B̄|
///     over F × B, then with u = (A − B̄)/|A − B̄|, a is the only site of F with the largest u·X
///     (another a′ with u·A′ ≥ u·A has |A′ − B̄| ≥ u·(A′ − B̄) ≥ |A − B̄| with equality only if
///     A′ = A) and b̄ the only one of B̄ with the smallest: both are strict corners of their
///     hulls. The same holds for the farthest site of one side from a given point, and the sites
///     of a side nearest to a point [0, u] of Ω by the sweep rule are those with the largest
///     u·X: corners, or sites on a hull edge. `front_extremes` and `back_extremes` hold every
///     hull vertex (dimension 2) or every site (dimension ≤ 1), a superset of those.
/// *Cost.* Two planar Delaunay triangulations, O(n log n); the Ω sites sorted by direction.

#include <functional>
#include <span>
#include <utility>
#include <vector>

#include "t2/kernel/point.hpp"
#include "t2/triangulation/triangulation.hpp"

namespace t2 {

/// The candidates of the proximity problems (see the file comment).
struct ProximitySites {
  using Index = Triangulation::Index;  ///< site indices
  /// kept[i]: the smallest index of a site equal to site i (i itself for the first of them).
  std::vector<Index> kept;
  /// The planar Delaunay edges of each side between kept sites, (a, b) with a < b; for a side
  /// whose sites are collinear, its consecutive sites along their line.
  std::vector<std::pair<Index, Index>> edges;
  std::vector<Index> front;  ///< the kept sites on the front side, ascending
  std::vector<Index> back;   ///< the kept sites on the back side, ascending
  std::vector<Index> omega;  ///< the kept sites on Ω, ascending
  /// The front side's hull vertices (every kept front site if they span a dimension ≤ 1),
  /// ascending.
  std::vector<Index> front_extremes;
  /// The back side's hull vertices, likewise.
  std::vector<Index> back_extremes;
};

/// What a traced algorithm is shown of each side with sites: its planar Delaunay triangulation
/// (of the drawn positions) and the input index of each of its vertices.
using SideView = std::function<void(const Triangulation& tr, std::span<const Triangulation::Index> input_of)>;

/// The candidates of `points` (see the file comment). Throws `BadInput` for more points than
/// the triangulation's 32-bit indices hold. `view`, when given, is shown each side's
/// triangulation before it is dropped (the traced spanning tree draws it).
ProximitySites proximity_sites(std::span<const Point> points, const SideView& view = {});

}  // namespace t2
