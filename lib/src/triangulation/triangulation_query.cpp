// The queries of t2::Triangulation (triangulation.hpp): edges, the public exact locate and
// nearest_vertex on all of T². The stars (incident_faces, neighbors) are inline in the header.
#include <stdexcept>
#include <string>
#include <vector>

#include "t2/kernel/distance.hpp"
#include "t2/kernel/error.hpp"
#include "t2/kernel/orient.hpp"
#include "t2/triangulation/antipodal_edge.hpp"
#include "t2/triangulation/face_kind.hpp"
#include "t2/triangulation/triangulation.hpp"

namespace t2 {

std::vector<Triangulation::Index> Triangulation::edges() const {
  std::vector<Index> out;
  out.reserve(n_.size() / 2);
  for (Index h = 0; h < n_.size(); ++h)
    if (h < n_[h]) out.push_back(h);
  return out;
}

namespace {

using Index = Triangulation::Index;
using Location = Triangulation::Location;

/// What p is in the finite face t, not flat, given the exact sides s of its edges, all ≥ 0
/// (so p is in the closed face: the closed cone of a proper face; the closed lune, an
/// intersection of two closed hemispheres, antipodal_edge.hpp).
Location classify(const Triangulation& tr, Index t, const Sign s[3], const Point& p) {
  const int zeros = (s[0] == ZERO) + (s[1] == ZERO) + (s[2] == ZERO);
  if (zeros == 0) return {Location::face, t, 0};
  for (int i = 0; i < 3; ++i)
    if (tr.point(tr.vertex(t, i)) == p) return {Location::vertex, t, i};
  // A proper face: two zeros put p on the ray of a vertex, which is p itself (above); one
  // zero, inside that edge. A lune (w, z, ¬z): its two edges through w lie on one great
  // circle, so their sides are equal; one zero is the antipodal edge, two are the half circle
  // z → w → ¬z, in one of its arcs.
  for (int i = 0; i < 3; ++i) {
    if (s[i] != ZERO) continue;
    const Point &a = tr.point(tr.vertex(t, (i + 1) % 3)), &b = tr.point(tr.vertex(t, (i + 2) % 3));
    if (a == antipode(b) ? zeros == 1 : (zeros == 1 || inside_arc(a, b, p))) return {Location::edge, t, i};
  }
  throw std::logic_error("locate: a point on the boundary of face " + std::to_string(t) + " and on none of its edges");
}

/// p strictly inside the edge opposite slot i of t (not flat). When a flat face lies across
/// that edge, p may be a vertex hidden inside the edge: the middle vertex of a flat face, and
/// flat faces may lie on one another (figure 5.19, Algorithm 9 only). Those few faces are
/// scanned for it; otherwise the edge stands (overlapping edges of flat faces are not refined).
Location refine(const Triangulation& tr, Location loc, const Point& p) {
  if (face_kind(tr, tr.neighbor(loc.t, loc.i)) != FaceKind::flat) return loc;
  for (Index f = 0; f < tr.size(); ++f)
    if (face_kind(tr, f) == FaceKind::flat)
      for (int j = 0; j < 3; ++j)
        if (tr.point(tr.vertex(f, j)) == p) return {Location::vertex, f, j};
  return loc;
}

/// The edge-sides of p in the finite face t, and whether p is in the closed face (no side < 0).
bool in_closed_face(const Triangulation& tr, Index t, const Point& p, Sign s[3]) {
  for (int i = 0; i < 3; ++i)
    if ((s[i] = side_of_edge(tr, t, i, p)) == NEGATIVE) return false;
  return true;
}

}  // namespace

//> locate-t2
// The visibility walk on T². From face t, cross an edge (other than the one we came through,
// starting at a random one) that has p strictly on its far side, by the exact side_of_edge of
// face_kind.hpp; stop at a face no edge of which separates p — p is in the closed face: the
// closed cone of a proper face, the closed lune — or on entering an infinite face: p is strictly
// beyond its hull edge, outside the closed hull. A flat face never stops the walk unless p lies
// on its great circle. Correctness needs no termination proof: on a planar Delaunay
// triangulation and a front p the walk ends (triangulation.hpp, the lifting argument), but on
// the sphere a visibility walk may circle, so after 4·(faces) + 64 steps, or at a flat face,
// a scan of the faces answers instead (exact as well). Either way the answer is checked face by
// face with the same exact sides, so it is right for every p of T².
Triangulation::Location Triangulation::locate(const Point& p, Index hint) const {
  if (dimension_ != 2)
    throw std::logic_error("locate: the triangulation has no triangle (dimension " + std::to_string(dimension_) + ")");
  std::uint32_t rng = 2463534242u;
  Index t = static_cast<Index>(hint % size());
  int from = -1;  // the slot of the edge we came through: p is strictly inside it
  Sign s[3];
  for (std::size_t steps = 4 * size() + 64; steps > 0; --steps) {
    const int inf = slot(t, infinite);
    if (inf >= 0) {
      if (from >= 0 || orient(points_[vertex(t, next(inf))], points_[vertex(t, prev(inf))], p) > 0)
        return {Location::face, t, inf};
      t = neighbor(t, inf);  // p is on the hull's side of that edge (or on its line): step in
      from = -1;
      continue;
    }
    rng ^= rng << 13, rng ^= rng >> 17, rng ^= rng << 5;
    const int r = static_cast<int>(rng % 3);
    int cross = -1;
    for (int k = 0; k < 3 && cross < 0; ++k) {
      const int i = (r + k) % 3;
      s[i] = i == from ? POSITIVE : side_of_edge(*this, t, i, p);
      if (s[i] == NEGATIVE) cross = i;
    }
    if (cross < 0) {
      if (face_kind(*this, t) == FaceKind::flat) break;  // p on its circle: the scan decides
      const Location loc = classify(*this, t, s, p);
      return loc.kind == Location::edge ? refine(*this, loc, p) : loc;
    }
    from = static_cast<int>(twin(t, cross) % 3);
    t = neighbor(t, cross);
  }
  for (Index f = 0; f < size(); ++f) {
    if (is_infinite(f) || face_kind(*this, f) == FaceKind::flat || !in_closed_face(*this, f, p, s)) continue;
    const Location loc = classify(*this, f, s, p);
    return loc.kind == Location::edge ? refine(*this, loc, p) : loc;
  }
  for (Index f = 0; f < size(); ++f)
    if (const int inf = slot(f, infinite); inf >= 0 && orient(points_[vertex(f, next(inf))], points_[vertex(f, prev(inf))], p) > 0)
      return {Location::face, f, inf};
  throw std::logic_error("locate: " + to_string(p) + " is in no face (the triangulation does not tile)");
}
//< locate-t2

namespace {

/// The nearest vertex to p by a scan of all vertices (exact). For p on Ω, compare_distance is
/// undefined between a front and a back site: the sites on Ω are compared first (the angle
/// rule), a site on Ω at most 90° from p is as near as every proper site or nearer (the 90°
/// convention), and otherwise the proper sites must all lie on one side.
Index nearest_by_scan(const Triangulation& tr, const Point& p) {
  Index best[3] = {Triangulation::none, Triangulation::none, Triangulation::none};  // back, Ω, front
  for (Index v = 0; v < tr.points().size(); ++v) {
    if (tr.face_of(v) == Triangulation::none) continue;
    Index& b = best[tr.point(v).w() < 0 ? 0 : tr.point(v).w() == 0 ? 1 : 2];
    if (b == Triangulation::none || compare_distance(tr.point(v), tr.point(b), p) == NEGATIVE) b = v;
  }
  if (p.w() != 0) {  // every pair is comparable
    Index v = Triangulation::none;
    for (Index b : best)
      if (b != Triangulation::none && (v == Triangulation::none || compare_distance(tr.point(b), tr.point(v), p) == NEGATIVE)) v = b;
    return v;
  }
  const Index z = best[1], back = best[0], front = best[2];
  bool z_nearest = z != Triangulation::none;  // no proper site strictly nearer than z
  for (Index b : {back, front})
    if (z_nearest && b != Triangulation::none) z_nearest = compare_distance(tr.point(b), tr.point(z), p) != NEGATIVE;
  if (z_nearest) return z;
  if (back != Triangulation::none && front != Triangulation::none)
    throw Undefined("nearest_vertex: " + to_string(p) + " on Omega is at no defined distance order between the front site " +
                    to_string(tr.point(front)) + " and the back site " + to_string(tr.point(back)) +
                    " (compare_distance: from a point of Omega, a front and a back site are not comparable), "
                    "and no site on Omega is nearer");
  return back != Triangulation::none ? back : front;
}

}  // namespace

//> nearest-vertex
// Why the greedy walk stops at a nearest vertex of a Delaunay triangulation, for a proper point
// p on side σ (front or back) when some site lies on σ.
//  (i) Seen from p, compare_distance ranks every site on σ before every site on Ω (at +∞) and
//      those before every site on −σ (beyond infinity). So the nearest sites lie on σ, and a
//      walk that moves only to strictly nearer vertices never leaves σ once it is there. It
//      starts on σ: at a vertex on σ of the face that holds p, or one found by a scan.
// (ii) Between two sites on σ, compare_distance is the Euclidean comparison of the drawn
//      positions (the back ones through their antipodes). The T² Delaunay contains the planar
//      Delaunay triangulation D_σ of the sites on σ: delaunay_t2.hpp copies every finite
//      triangle of each side's triangulation (the back one mirrored), and for front-only input
//      the triangulation is D_σ itself. When the sites on σ are collinear, D_σ is their path
//      along the line, whose edges a–b are those of two faces touching Ω, (b, a, x) and
//      (a, b, y); both are replaced by v∞ only if both turn clockwise, which by property 2 of
//      delaunay_t2.hpp puts every site on each closed side of the line a ∨ b — all collinear,
//      no triangulation at all. So every edge of D_σ is an edge here.
// (iii) The planar lemma: let v be a vertex of D_σ that is not a nearest one to p. The closed
//      Voronoi cell of v is convex with nonempty interior (the vertices are distinct), so it is
//      the intersection of the closed half-planes {x : |x − v| ≤ |x − w|} of the sites w whose
//      cells share an edge with it; p lies outside it, hence |p − w| < |p − v| for one of those
//      w. Two cells share an edge exactly when the sites are joined in the Delaunay
//      subdivision, which every Delaunay triangulation refines (the perturbation of
//      delaunay.hpp only adds diagonals to its cocircular faces): w is a neighbour of v.
// Each step makes the distance strictly smaller, so no vertex repeats and the walk stops, at a
// vertex of σ with no nearer neighbour on σ: by (iii) a nearest site of σ, by (i) of all.
//
// Where it does not hold, and what is done instead (a scan of the vertices, O(n), exact):
//  - p proper with no site on its side: the nearest site is then on Ω (the angle rule) or, with
//    none there, the *farthest* drawn site of the other side, and a greedy walk on the nearest-
//    point Delaunay graph can stop at a local maximum of the distance that is not the global
//    one (sites on an ellipse, p̄ off its centre along the major axis: both ends are local
//    maxima among their neighbours, one is farther). The farthest-point diagram needs the
//    farthest-point triangulation, which this is not.
//  - p on Ω: compare_distance orders a front and a back site only relative to the sites of Ω;
//    nearest_by_scan says the rule, and throws Undefined where no rule decides.
Triangulation::Index Triangulation::nearest_vertex(const Point& p, Index hint) const {
  const Location loc = locate(p, hint);
  if (loc.kind == Location::vertex) return vertex(loc.t, loc.i);
  if (p.w() == 0) return nearest_by_scan(*this, p);
  const bool front = p.w() > 0;
  auto on_side = [&](Index x) { return x != infinite && (front ? points_[x].w() > 0 : points_[x].w() < 0); };
  Index v = none;
  for (int k = 0; k < 3 && v == none; ++k)
    if (on_side(vertex(loc.t, k))) v = vertex(loc.t, k);
  for (Index x = 0; x < points_.size() && v == none; ++x)
    if (face_of(x) != none && on_side(x)) v = x;
  if (v == none) return nearest_by_scan(*this, p);  // no site on p's side
  for (bool moved = true; moved;) {
    moved = false;
    for (Index w : neighbors(v)) {
      if (w == infinite || compare_distance(points_[w], points_[v], p) != NEGATIVE) continue;
      v = w;
      moved = true;
      break;
    }
  }
  return v;
}
//< nearest-vertex

}  // namespace t2
