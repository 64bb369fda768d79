#pragma once
/// @file delaunay_t2.hpp
/// @brief The Delaunay triangulation of points on both sides of T²: the dual of the T² Voronoi
/// diagram, built from the planar triangulations of each side and a merge along Ω.
///
/// **Definition and proofs: chapter 10, section 8** (chapters/10-delaunay/chapter-3.md), written
/// once there for this file and for chapter 11. In short: with F the front sites and B the back
/// ones, each hemisphere is divided as the plane is by the Euclidean Voronoi diagram of its own
/// sites (Lemma 1), Ω is a chain of Voronoi edges between a front and a back owner, and the dual
/// is the planar Delaunay triangulation of F, that of B (counter-clockwise in T², so mirrored as
/// drawn), and one *band* face per break on Ω: (a₂, a₁, b) for a front hull edge a₁ → a₂ and the
/// back site b extreme (drawn) in the direction −n of its outer normal, (b₁, b₂, a) likewise for
/// a back hull edge. A face's disk is the kernel's `in_circle` (incircle.hpp): Euclidean for
/// one-sided faces, a lune for a band face. Theorem 2 there proves the disks empty, the band
/// closed (an exact merge of the two hulls' normals: `detail::cross_of_differences`, angle.hpp),
/// and that a clockwise band face means the sites have a hull. Implementation choices recorded
/// here: a flat face of an antipodal pair a, ¬a is recorded as Algorithm 9 does, by the sphere
/// bisector of the angle the two lunes leave at a (face_kind.hpp, `Triangulation::antipodal_edges()`),
/// so that the exact walk of `locate` reads both constructions alike; with a hull, each edge
/// between a clockwise band face and a counter-clockwise face becomes a hull edge with an
/// infinite triangle (v∞); the tests certify that the faces tile the sphere (or the hull) by
/// counting, exactly, the faces that hold random points.
///
/// **Sites on Ω** (Z, directions). Seen from a proper point every site on its own side is
/// nearer than any site on Ω, so Lemma 1 still divides each hemisphere that holds sites. On Ω the
/// distance between two directions is their angle (seed 000, §4.3.1, figure 4.15) and a proper
/// site is as far as the lunes of incircle.hpp say: 90°. So a point [0, u] of Ω belongs to the
/// site of Z nearest in angle when that angle is below 90°, and to the front and back owners
/// of Lemma 1 otherwise — the band survives only in the gaps of Z wider than π. The dual (built by
/// delaunay_ring.hpp in one sweep of u): the planar triangulations of F and B; a face (a₂, a₁, z)
/// for each front hull edge whose normal z owns, (b₁, b₂, z) likewise behind; for consecutive
/// sites z₁, z₂ of Z less than π apart the faces (z₁, z₂, a) and (z₂, z₁, b) with a, b the
/// owners at the middle of the arc; at each end of a gap wider than π a face (a, z, b); and the
/// band in the gaps. Their disks are `in_face_disk` (face_disk.hpp): the kernel's lunes, whose
/// ties on Ω (every site on the open half of Ω of a face (a₁, a₂, z) is *on* its circle) the
/// angle breaks, and for (z₁, z₂, a) the lune centred at the middle of the arc. Theorem 2 (a)
/// holds for them as for the band: a face's disk is what its Voronoi vertex sees nearer than its
/// vertices, and each vertex is an owner there. It is also the plane's answer: with every site
/// of Z replaced by a front point at one common radius t along its direction, the planar
/// Delaunay triangulation has the same triangles for t large (test_delaunay_omega.cpp).
/// *Undefined.* When F or B is empty and Z lies in no open half of Ω, the empty hemisphere has
/// no site of its own: it would be divided among the sites of Z by angles seen from a proper
/// point (seed 000, figure 4.16), which change with the origin, and its faces would have three
/// vertices on Ω, all collinear. `delaunay` throws `Undefined` naming three of those sites (or
/// an antipodal pair). When Z lies in an open half, the sites lie in an open hemisphere and the
/// empty side's owner is v∞: those faces are the infinite ones. All points on Ω are collinear
/// (they lie on the line Ω): dimension 1, no triangle, like any collinear input. A flat face
/// without an antipodal pair (a tie: a back site exactly on the line of a front hull edge, a
/// hull edge parallel to a site of Z) throws `Undefined`.
/// **Cost.** Two planar triangulations, whose arrays are copied into the result (the back one
/// mirrored), and a sweep of the hulls and of Z: O(n log n). Only the faces touching Ω are
/// linked through a hash map, O(hull + |Z|).

#include <algorithm>
#include <array>
#include <cstdint>
#include <span>
#include <stdexcept>
#include <string>
#include <unordered_map>
#include <vector>

#include "t2/kernel/angle.hpp"
#include "t2/kernel/error.hpp"
#include "t2/kernel/lexicographic.hpp"
#include "t2/kernel/orient.hpp"
#include "t2/kernel/point.hpp"
#include "t2/triangulation/delaunay.hpp"
#include "t2/triangulation/delaunay_ring.hpp"
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

/// The points of Ω among `input` (indices `omega`) sorted counter-clockwise by direction from
/// (1, 0), each direction once: the later equal points are recorded as duplicates in `tr`.
inline std::vector<Triangulation::Index> omega_order(std::span<const Point> input,
                                                     std::vector<Triangulation::Index> omega, Triangulation& tr) {
  using Index = Triangulation::Index;
  auto half = [&](Index a) { return input[a].y() > 0 || (input[a].y() == 0 && input[a].x() > 0) ? 0 : 1; };
  auto cmp = [&](Index a, Index b) {  // NEGATIVE: a's direction first
    if (half(a) != half(b)) return half(a) < half(b) ? NEGATIVE : POSITIVE;
    return -cross_omega(input[a], input[b]);
  };
  std::sort(omega.begin(), omega.end(), [&](Index a, Index b) {
    const Sign s = cmp(a, b);
    return s != ZERO ? s == NEGATIVE : a < b;
  });
  std::vector<Index> z;
  for (Index a : omega)
    if (!z.empty() && cmp(z.back(), a) == ZERO)
      tr.add_duplicate(a, z.back());
    else
      z.push_back(a);
  return z;
}

/// Throws `Undefined` when the sites on Ω (sorted, `z`) lie in no open half of Ω while one side
/// of T² holds no site: that hemisphere would be divided among the sites on Ω by angles seen
/// from a proper point, which depend on the origin (delaunay_t2.hpp).
inline void check_empty_side(std::span<const Point> input, const std::vector<Triangulation::Index>& z,
                             const char* side) {
  const std::size_t k = z.size();
  auto gap_over_pi = [&](std::size_t j) {  // the arc from z[j] to z[j+1] exceeds π
    const Sign c = cross_omega(input[z[j]], input[z[(j + 1) % k]]);
    return c == NEGATIVE || (c == ZERO && dot_omega(input[z[j]], input[z[(j + 1) % k]]) == POSITIVE);
  };
  for (std::size_t j = 0; j < k; ++j)
    if (gap_over_pi(j)) return;
  std::string names;  // an antipodal pair, or three points around Ω
  for (std::size_t j = 0; j < k && names.empty(); ++j)
    if (cross_omega(input[z[j]], input[z[(j + 1) % k]]) == ZERO)
      names = std::to_string(z[j]) + " and " + std::to_string(z[(j + 1) % k]) + " (antipodal)";
  if (names.empty()) {
    std::size_t a = 1;  // the last point less than π after z[0]
    while (a + 1 < k && cross_omega(input[z[0]], input[z[a + 1]]) == POSITIVE) ++a;
    names = std::to_string(z[0]) + ", " + std::to_string(z[a]) + " and " + std::to_string(z[(a + 1) % k]);
  }
  throw Undefined("delaunay: the points " + names + " on Omega lie in no open half of it and no point is on the " +
                  side + " side: that hemisphere has no Delaunay triangulation independent of the origin");
}

/// The orientation of a face touching Ω (ZERO for a face at v∞); throws `Undefined` for a flat
/// face without an antipodal pair (a tie on Ω).
inline Sign face_orient(std::span<const Point> input, const std::array<Triangulation::Index, 3>& t) {
  constexpr Triangulation::Index inf = Triangulation::infinite;
  if (t[0] == inf || t[1] == inf || t[2] == inf) return ZERO;
  const Point &a = input[t[0]], &b = input[t[1]], &c = input[t[2]];
  const Sign o = orient(a, b, c);
  if (o == ZERO && !(a == antipode(b) || b == antipode(c) || c == antipode(a)))
    throw Undefined("delaunay: the points " + std::to_string(t[0]) + ", " + std::to_string(t[1]) + ", " +
                    std::to_string(t[2]) + " make a flat face without an antipodal pair (a tie on Omega)");
  return o;
}

/// The faces touching Ω unchanged, once `face_orient` has checked each (the whole sphere).
inline std::vector<std::array<Triangulation::Index, 3>> check_flat(
    std::span<const Point> input, std::vector<std::array<Triangulation::Index, 3>> faces) {
  for (const auto& t : faces) face_orient(input, t);
  return faces;
}

/// The faces touching Ω with v∞ in place of the clockwise ones (property 3 of delaunay_t2.hpp):
/// an edge between a clockwise face and a counter-clockwise one (or a planar triangle) becomes
/// a hull edge with its infinite triangle. Throws `Undefined` for a flat face without an
/// antipodal pair.
inline std::vector<std::array<Triangulation::Index, 3>> replace_clockwise(
    std::span<const Point> input, std::vector<std::array<Triangulation::Index, 3>> faces) {
  using Index = Triangulation::Index;
  constexpr Index inf = Triangulation::infinite;
  std::vector<char> clockwise(faces.size(), 0);
  bool any = false;
  for (std::size_t f = 0; f < faces.size(); ++f)
    if (face_orient(input, faces[f]) == NEGATIVE) clockwise[f] = any = true;
  if (!any) return faces;
  std::unordered_map<std::uint64_t, std::size_t> owner;  // the faces touching Ω only: O(hull)
  auto key = [](Index u, Index v) { return (std::uint64_t(u) << 32) | v; };
  for (std::size_t f = 0; f < faces.size(); ++f)
    for (int i = 0; i < 3; ++i) owner[key(faces[f][i], faces[f][(i + 1) % 3])] = f;
  std::vector<std::array<Index, 3>> kept;
  for (std::size_t f = 0; f < faces.size(); ++f) {
    if (!clockwise[f]) {
      kept.push_back(faces[f]);
      continue;
    }
    for (int i = 0; i < 3; ++i) {
      const Index x = faces[f][i], y = faces[f][(i + 1) % 3];
      const auto it = owner.find(key(y, x));  // absent: a planar triangle, never clockwise
      if (it == owner.end() || !clockwise[it->second]) kept.push_back({x, y, inf});
    }
  }
  return kept;
}

//> delaunay-t2-copy
/// Appends the triangles of the planar triangulation `t` to the arrays (v, n): vertex u becomes
/// index[u], `mirror` reverses each triangle (slots 1 and 2 swap: the back side), the infinite
/// triangles are left out unless `infinite`. Twins inside t are copied; a half-edge whose twin
/// is left out is recorded in `open` under its directed edge, for the faces across Ω.
inline void append_planar(const Triangulation& t, const std::vector<Triangulation::Index>& index,
                          bool mirror, bool infinite, std::vector<Triangulation::Index>& v,
                          std::vector<Triangulation::Index>& n,
                          std::unordered_map<std::uint64_t, Triangulation::Index>& open) {
  using Index = Triangulation::Index;
  const int slot[3] = {0, mirror ? 2 : 1, mirror ? 1 : 2};
  std::vector<Index> id(t.size(), Triangulation::none);
  Index next = static_cast<Index>(v.size() / 3);
  for (Index s = 0; s < t.size(); ++s)
    if (infinite || !t.is_infinite(s)) id[s] = next++;
  v.resize(3 * std::size_t(next));
  n.resize(3 * std::size_t(next));
  for (Index s = 0; s < t.size(); ++s) {
    if (id[s] == Triangulation::none) continue;
    for (int i = 0; i < 3; ++i) {
      const Index u = t.vertex(s, i);
      v[3 * id[s] + slot[i]] = u == Triangulation::infinite ? u : index[u];
    }
    for (int i = 0; i < 3; ++i) {
      const Index e = t.twin(s, i), h = 3 * id[s] + slot[i];
      if (id[e / 3] != Triangulation::none) {
        n[h] = 3 * id[e / 3] + slot[e % 3];
      } else {
        const Index a = v[3 * id[s] + (slot[i] + 1) % 3], b = v[3 * id[s] + (slot[i] + 2) % 3];
        open[(std::uint64_t(a) << 32) | b] = h;
      }
    }
  }
}
//< delaunay-t2-copy

/// Appends `faces` to (v, n) and links each of their half-edges with its opposite: another of
/// `faces` or a half-edge of `open`.
inline void append_linked(const std::vector<std::array<Triangulation::Index, 3>>& faces,
                          std::vector<Triangulation::Index>& v, std::vector<Triangulation::Index>& n,
                          std::unordered_map<std::uint64_t, Triangulation::Index>& open) {
  using Index = Triangulation::Index;
  auto key = [](Index a, Index b) { return (std::uint64_t(a) << 32) | b; };
  const Index first = static_cast<Index>(v.size());
  for (const auto& t : faces)
    for (int i = 0; i < 3; ++i) {
      v.push_back(t[i]);
      n.push_back(Triangulation::none);
      open[key(t[(i + 1) % 3], t[(i + 2) % 3])] = static_cast<Index>(v.size() - 1);
    }
  for (Index h = first; h < v.size(); ++h) {
    const Index t = h / 3, i = h % 3;
    const auto it = open.find(key(v[3 * t + (i + 2) % 3], v[3 * t + (i + 1) % 3]));
    if (it == open.end()) throw std::logic_error("delaunay_t2: a face across Omega has no neighbour");
    n[h] = it->second;
    n[it->second] = h;
  }
}

/// Records every antipodal edge of tr (face_kind.hpp): only faces touching Ω, from `first` on,
/// can hold one (a planar triangle has its three vertices on one side). For the edge a → b of
/// the face t = (w, a, b) and the face (u, b, a) across it, the record is {a, b, u, w}: the
/// edge runs along the sphere bisector of the angle u a w, which lies inside the two lunes
/// (antipodal_edge.hpp, *Any lunes*), so the faces tile T² with it.
inline void record_antipodal_edges(Triangulation& tr, Triangulation::Index first) {
  using Index = Triangulation::Index;
  for (Index h = 3 * first; h < 3 * tr.size(); ++h) {
    const Index a = tr.org(h), b = tr.dest(h), e = tr.twin(h);
    if (e < h || a == Triangulation::infinite || b == Triangulation::infinite) continue;
    if (!(tr.point(a) == antipode(tr.point(b)))) continue;
    const Index w = tr.vertex(h / 3, static_cast<int>(h % 3)), u = tr.vertex(e / 3, static_cast<int>(e % 3));
    if (w != Triangulation::infinite && u != Triangulation::infinite) tr.add_antipodal_edge({a, b, u, w});
  }
}

//> delaunay-t2
/// The Delaunay triangulation of points of T² not all in front (see the file comment); the
/// planar triangulations of each side use traits K. With `whole_sphere` the clockwise faces of
/// property 3 are kept instead of v∞ (the Delaunay complex, t2/voronoi/complex.hpp): the
/// result then breaks invariant 1 of triangulation.hpp and is read only as a list of faces.
template <class K>
Triangulation delaunay_t2(std::span<const Point> input, const K& kernel, bool whole_sphere) {
  using Index = Triangulation::Index;
  std::vector<Index> front, back, omega;
  for (Index k = 0; k < input.size(); ++k)
    (input[k].w() > 0 ? front : input[k].w() < 0 ? back : omega).push_back(k);
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
  const std::vector<Index> z = omega_order(input, omega, tr);
  if (!z.empty() && (front.empty() || back.empty()))
    check_empty_side(input, z, front.empty() ? "front" : "back");
  std::vector<Point> fp, bp;  // the front points, and the antipodes of the back ones (drawn B̄)
  fp.reserve(front.size());
  bp.reserve(back.size());
  for (Index k : front) fp.push_back(input[k]);
  for (Index k : back) bp.push_back(antipode(input[k]));
  const Triangulation df = delaunay_with(std::span<const Point>(fp), kernel);
  const Triangulation db = delaunay_with(std::span<const Point>(bp), kernel);
  for (auto [d, k] : df.duplicates()) tr.add_duplicate(front[d], front[k]);
  for (auto [d, k] : db.duplicates()) tr.add_duplicate(back[d], back[k]);
  // Copy the planar triangles (the back ones mirrored: counter-clockwise in T²), then the faces
  // touching Ω, linked to the hull edges left open.
  std::vector<Index> v, n;
  v.reserve(3 * (df.size() + db.size() + 2 * z.size() + 4));
  n.reserve(v.capacity());
  std::unordered_map<std::uint64_t, Index> open;
  const bool back_only = front.empty() && z.empty();  // the mirror of db, v∞ included
  if (df.dimension() == 2) append_planar(df, front, false, false, v, n, open);
  if (db.dimension() == 2) append_planar(db, back, true, back_only, v, n, open);
  const Index ring_first = static_cast<Index>(v.size() / 3);  // the faces touching Ω from here on
  if (!back_only) {
    RingSide fs{&fp, front.empty() ? std::vector<Index>{} : boundary_cycle(df), front};
    RingSide bs{&bp, back.empty() ? std::vector<Index>{} : boundary_cycle(db), back};
    std::vector<std::array<Index, 3>> ring;
    ring_faces(fs, bs, tr.points(), z, ring);
    append_linked(whole_sphere ? check_flat(input, std::move(ring)) : replace_clockwise(input, std::move(ring)), v, n,
                  open);
  }
  tr.assign(std::move(v), std::move(n));
  record_antipodal_edges(tr, ring_first);
  tr.finish();
  return tr;
}
//< delaunay-t2

}  // namespace t2::detail
