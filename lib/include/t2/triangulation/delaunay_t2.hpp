#pragma once
/// @file delaunay_t2.hpp
/// @brief The Delaunay triangulation of points on both sides of T²: the dual of the T² Voronoi
/// diagram, built from the planar triangulations of each side and a merge along Ω.
///
/// **The Voronoi diagram it is dual to.** Distances as in §4.3.1 of seed 000 (distance.hpp): on
/// one side the Euclidean distance; across sides "beyond infinity", where the *larger* the
/// Euclidean distance between the drawn positions, the *nearer*, and the antipode is the
/// farthest point of all. Let F be the sites in front (w > 0) and B those behind (w < 0), both
/// non-empty. (1) A front query point is nearer to every front site than to any back site, so the
/// front hemisphere is divided exactly as the Euclidean Voronoi diagram of F divides the plane;
/// the back hemisphere likewise by B. (2) On Ω the two meet. Follow a front point q off to the
/// point at infinity ζ = [0, u]: the nearest front site is eventually the one extreme in the
/// direction u (|Q − A| = |Q| − u·A + o(1) for Q = t u, the sweep rule of §4.3.1). A back point
/// tends to [0, u] when its drawn position runs off in the direction −u, so the back site owning
/// ζ from behind is the one whose drawn position B̄ is extreme in the direction −u. Hence Ω is a
/// chain of Voronoi edges, each between a front site a and a back site b, broken at two kinds of
/// Voronoi vertices: where the front owner changes — u is the outer normal n of a hull edge a₁ a₂
/// of F — and where the back owner changes — −u is the outer normal of a hull edge b̄₁ b̄₂ of the
/// drawn B̄. (In general position no two breaks coincide; ties are broken front first.)
///
/// **The dual.** Front Voronoi vertices are the Delaunay triangles of F, back ones those of B
/// (counter-clockwise in T²: the drawn back side is mirrored, so they are the clockwise triangles
/// of the drawn B̄). Each break on Ω gives a *band* face: (a₂, a₁, b) for the front hull edge
/// a₁ → a₂ (counter-clockwise around F) and the current back owner b, or (b₁, b₂, a) for the
/// drawn hull edge b̄₁ → b̄₂ and the current front owner a. Walking u once around the circle
/// merges the two sequences of hull edges by the angle of their normals (an exact merge of
/// directions: `detail::cross_of_differences`, angle.hpp), so the band closes up between the two hulls.
/// The disk of each face — the points nearer to its Voronoi vertex than its vertices — is the
/// inside of the kernel's `in_circle` (incircle.hpp): the Euclidean disk for one-sided faces, for
/// a band face the lune between the line a₁ a₂ (front) and its parallel through b (back).
///
/// **Properties, with proofs.**
///  1. *Empty disks.* Every face's disk holds no site strictly (and in general position only
///     the Delaunay faces have empty disks, which the brute-force test checks). For one-sided
///     faces by (1). For the band face (a₂, a₁, b): a front site d is inside iff it lies
///     strictly beyond the hull edge a₁ a₂ — none does; a back site d is inside iff its drawn
///     position is strictly further than b̄ in the direction −n — none is, b̄ being extreme.
///  2. *Orientation and the hull.* A band face (a₂, a₁, b) has orient = orient(A₁, A₂, B̄) of the
///     drawn positions (the back row has w < 0). If it is negative, then n·B̄ > n·A₁ for every
///     back site (b̄ minimizes n·B̄), so with ℓ = the line a₁ ∨ a₂, every site is on its closed
///     inner side and only front sites on the segment a₁ a₂ are on ℓ: the sites lie in an open
///     hemisphere (tilt ℓ about the midpoint of a₁ a₂) — the convex hull exists. Contrapositive:
///     without a hull every face turns counter-clockwise or is flat (orient = 0). Flat faces come
///     from an antipodal pair a, ¬a (b̄ = A at a corner of both hulls): the seed's degenerate
///     face of figure 5.18, a lune bounded by the line through a and its neighbour and the half
///     great circle from a to ¬a that crosses Ω at the bisector of a's normal cone — the
///     seed's "bisector of the angle u v w" is exactly the middle of the Voronoi edge a–¬a.
///  3. *With a hull* (all sites in an open hemisphere, e.g. a few back points near Ω) the
///     clockwise band faces are the Voronoi vertices "beyond" the hull, as the farthest-point
///     triangles are for front-only input; as there, they are replaced by v∞: each edge between
///     a clockwise face and a counter-clockwise one becomes a hull edge with an infinite
///     triangle. The tests certify that the result tiles the hull (below).
///  4. *Tiling.* A closed triangulated surface whose faces are all positively oriented spherical
///     triangles is a branched covering of the sphere; its degree is the number of faces that
///     contain any generic point. The tests count it at random points, exactly (orient), and
///     find 1: the triangles tile the sphere (or the hull, with v∞).
///
/// **Not implemented.** Points on Ω together with proper points (throws `Undefined`): by the
/// distances of §4.3.1 a site on Ω is nearer than no proper site to any proper point, so its
/// Voronoi cell is an arc of Ω whose extent the angle rule makes depend on the origin; its dual
/// needs a convention this file does not choose. All points on Ω are collinear (they lie on the
/// line Ω): dimension 1, no triangle, like any collinear input. A flat face without an antipodal
/// pair (a back site exactly on the line of a front hull edge, or the converse) throws `Undefined`.
/// Cost: two planar triangulations and a merge of the hulls, O(n log n).

#include <algorithm>
#include <array>
#include <span>
#include <string>
#include <unordered_map>
#include <vector>

#include "t2/angle.hpp"
#include "t2/error.hpp"
#include "t2/lexicographic.hpp"
#include "t2/orient.hpp"
#include "t2/point.hpp"
#include "t2/triangulation/delaunay.hpp"
#include "t2/triangulation/triangulation.hpp"

namespace t2::detail {

/// Are all points on one great circle (T²-collinear)? Exact.
inline bool all_collinear_t2(std::span<const Point> pts) {
  if (pts.empty()) return true;
  const Point& p = pts[0];
  for (const Point& q : pts) {
    if (q == p || q == antipode(p)) continue;
    for (const Point& r : pts)
      if (orient(p, q, r) != ZERO) return false;
    return true;
  }
  return true;
}

/// The counter-clockwise boundary of a planar triangulation of front points as a cycle of
/// vertices, starting at a strict corner: the hull for dimension 2, p₀ … p_m … p₁ along the line
/// for dimension 1, the one vertex for dimension 0.
inline std::vector<Triangulation::Index> boundary_cycle(const Triangulation& t) {
  using Index = Triangulation::Index;
  std::vector<Index> c;
  if (t.dimension() == 2) {
    std::unordered_map<Index, Index> next;
    for (auto [a, b] : t.hull_edges()) next[a] = b;
    Index v = t.hull_edges().front().first;
    for (std::size_t k = 0; k < next.size(); ++k, v = next[v]) c.push_back(v);
    const auto& p = t.points();
    const std::size_t k = c.size();
    std::size_t s = 0;  // a corner: the edges before and after it are not parallel
    while (cross_of_differences(p[c[(s + k - 1) % k]], p[c[s]], p[c[s]], p[c[(s + 1) % k]]) == ZERO) ++s;
    std::rotate(c.begin(), c.begin() + static_cast<std::ptrdiff_t>(s), c.end());
    return c;
  }
  std::vector<char> dropped(t.points().size(), 0);
  for (auto [d, k] : t.duplicates()) dropped[d] = 1;
  for (Index v = 0; v < t.points().size(); ++v)
    if (!dropped[v]) c.push_back(v);
  std::sort(c.begin(), c.end(), [&](Index a, Index b) { return compare_xy(t.point(a), t.point(b)) == NEGATIVE; });
  for (std::size_t m = c.size() - 1; m-- > 1;) c.push_back(c[m]);
  return c;
}

/// The band faces between the front boundary `fc` (indices into `fp`) and the drawn back
/// boundary `bc` (into `bp`, the antipodes of the back points), as (side, index) vertex triples
/// encoded by `vf` and `vb` (which map a front or back index to the output vertex index).
template <class VF, class VB>
void band_faces(const std::vector<Point>& fp, const std::vector<Triangulation::Index>& fc, const std::vector<Point>& bp,
                const std::vector<Triangulation::Index>& bc, VF vf, VB vb,
                std::vector<std::array<Triangulation::Index, 3>>& out) {
  const std::size_t k = fc.size(), l = bc.size();
  const std::size_t ke = k >= 2 ? k : 0, le = l >= 2 ? l : 0;
  // Event directions: front edge i is fc[i] → fc[i+1]; back edge j's break is at the direction
  // of bc[j+1] → bc[j] (the outer normal of the drawn edge, negated, turned like the edge).
  struct Dir {
    const Point *from, *to;
  };
  auto front_dir = [&](std::size_t i) { return Dir{&fp[fc[i]], &fp[fc[(i + 1) % k]]}; };
  auto back_dir = [&](std::size_t j) { return Dir{&bp[bc[(j + 1) % l]], &bp[bc[j]]}; };
  const Dir ref = ke > 0 ? front_dir(0) : back_dir(0);
  auto half = [&](const Dir& v) {
    const Sign c = cross_of_differences(*ref.from, *ref.to, *v.from, *v.to);
    return c == POSITIVE || (c == ZERO && dot_of_differences(*ref.from, *ref.to, *v.from, *v.to) == POSITIVE) ? 0 : 1;
  };
  auto compare = [&](const Dir& a, const Dir& b) {  // the angles from ref, in [0, 2π)
    const int ha = half(a), hb = half(b);
    if (ha != hb) return ha < hb ? NEGATIVE : POSITIVE;
    return -cross_of_differences(*a.from, *a.to, *b.from, *b.to);
  };
  std::size_t j0 = 0;  // the back events in increasing angle start after the one strict descent
  for (std::size_t j = 0; j < le; ++j)
    if (compare(back_dir((j + le - 1) % le), back_dir(j)) == POSITIVE) j0 = j;
  Triangulation::Index v = fc[0], w = bc[le > 0 ? j0 : 0];
  for (std::size_t i = 0, m = 0; i < ke || m < le;) {
    const std::size_t j = (j0 + m) % std::max<std::size_t>(le, 1);
    if (i < ke && (m == le || compare(front_dir(i), back_dir(j)) != POSITIVE)) {
      const Triangulation::Index a = fc[i], b = fc[(i + 1) % k];
      out.push_back({vf(b), vf(a), vb(w)});
      v = b;
      ++i;
    } else {
      const Triangulation::Index a = bc[j], b = bc[(j + 1) % l];
      out.push_back({vb(a), vb(b), vf(v)});
      w = b;
      ++m;
    }
  }
}

//> delaunay-t2
/// The Delaunay triangulation of points of T² not all in front (see the file comment); the
/// planar triangulations of each side use kernel K.
template <class K>
Triangulation delaunay_t2(std::span<const Point> input, const K& kernel) {
  using Index = Triangulation::Index;
  using Tri = std::array<Index, 3>;
  std::vector<Index> front, back;
  for (Index k = 0; k < input.size(); ++k) (input[k].w() > 0 ? front : back).push_back(k);
  Triangulation tr(std::vector<Point>(input.begin(), input.end()));
  if (all_collinear_t2(input)) {  // dimension ≤ 1: only the duplicates to find
    std::vector<Index> order(input.size());
    for (Index k = 0; k < order.size(); ++k) order[k] = k;
    std::sort(order.begin(), order.end(), [&](Index a, Index b) {
      const Sign s = compare_lexicographic(input[a], input[b]);
      return s != ZERO ? s == NEGATIVE : a < b;
    });
    bool all_equal = true;
    for (std::size_t m = 1, first = 0; m < order.size(); ++m) {
      if (input[order[first]] == input[order[m]])
        tr.add_duplicate(order[m], order[first]);
      else
        first = m, all_equal = false;
    }
    tr.set_dimension(input.empty() ? -1 : all_equal ? 0 : 1);
    tr.finish();
    return tr;
  }
  for (Index k : back)
    if (input[k].w() == 0)
      throw Undefined("delaunay: point " + std::to_string(k) + " = " + to_string(input[k]) +
                      " is on Omega together with proper points: not implemented (see delaunay_t2.hpp)");
  std::vector<Point> fp, bp;  // the front points, and the antipodes of the back ones (drawn B̄)
  for (Index k : front) fp.push_back(input[k]);
  for (Index k : back) bp.push_back(antipode(input[k]));
  const Triangulation df = delaunay_with(std::span<const Point>(fp), kernel);
  const Triangulation db = delaunay_with(std::span<const Point>(bp), kernel);
  for (auto [d, k] : df.duplicates()) tr.add_duplicate(front[d], front[k]);
  for (auto [d, k] : db.duplicates()) tr.add_duplicate(back[d], back[k]);
  auto vf = [&](Index v) { return front[v]; };
  auto vb = [&](Index v) { return v == Triangulation::infinite ? v : back[v]; };
  std::vector<Tri> faces;
  for (Index t = 0; t < db.size(); ++t)  // mirrored: reversed to turn counter-clockwise in T²
    if (front.empty() || !db.is_infinite(t)) faces.push_back({vb(db.vertex(t, 0)), vb(db.vertex(t, 2)), vb(db.vertex(t, 1))});
  if (!front.empty()) {
    for (const auto& t : df.finite_triangles()) faces.push_back({vf(t[0]), vf(t[1]), vf(t[2])});
    const std::size_t first_band = faces.size();
    band_faces(fp, boundary_cycle(df), bp, boundary_cycle(db), vf, vb, faces);
    std::vector<char> clockwise(faces.size(), 0);
    bool any = false;
    for (std::size_t f = first_band; f < faces.size(); ++f) {
      const Point &a = input[faces[f][0]], &b = input[faces[f][1]], &c = input[faces[f][2]];
      const Sign o = orient(a, b, c);
      if (o == ZERO && !(a == antipode(b) || b == antipode(c) || c == antipode(a)))
        throw Undefined("delaunay: points " + std::to_string(faces[f][0]) + ", " + std::to_string(faces[f][1]) + ", " +
                        std::to_string(faces[f][2]) +
                        " on both sides make a flat face without an antipodal pair: not implemented");
      if (o == NEGATIVE) clockwise[f] = any = true;
    }
    if (any) {  // a hull exists: v∞ replaces the clockwise faces (property 3)
      std::unordered_map<std::uint64_t, std::size_t> owner;
      auto key = [](Index u, Index v) { return (std::uint64_t(u) << 32) | v; };
      for (std::size_t f = 0; f < faces.size(); ++f)
        for (int i = 0; i < 3; ++i) owner[key(faces[f][i], faces[f][(i + 1) % 3])] = f;
      std::vector<Tri> kept;
      for (std::size_t f = 0; f < faces.size(); ++f) {
        if (!clockwise[f]) {
          kept.push_back(faces[f]);
          continue;
        }
        for (int i = 0; i < 3; ++i) {
          const Index x = faces[f][i], y = faces[f][(i + 1) % 3];
          if (!clockwise[owner.at(key(y, x))]) kept.push_back({x, y, Triangulation::infinite});
        }
      }
      faces = std::move(kept);
    }
  }
  tr.assemble(faces);
  tr.finish();
  return tr;
}
//< delaunay-t2

}  // namespace t2::detail
