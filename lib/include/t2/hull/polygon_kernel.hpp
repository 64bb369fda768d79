#pragma once
/// @file polygon_kernel.hpp
/// @brief The kernel of a polygon (the points that see all of it), unbounded ones included.
///
/// The kernel of a simple polygon P (counter-clockwise) is the set of points of P from which
/// every point of P is visible. **Lemma** (Lee and Preparata 1979). It is the intersection of the
/// closed half-planes to the left of the edges' lines. *Proof.* A point x of the kernel sees
/// each edge from its inner side (a point strictly right of edge e_i's line, near e_i, is
/// outside P, and so is the part of the segment x v beyond e_i for v on e_i), so x is left of
/// every edge line. Conversely, if x is left of every edge line and some point y of P were
/// hidden from x, the segment x y would leave P through some edge, crossing it from left to right,
/// which puts x right of that edge's line: a contradiction.
///
/// A half-plane of T² is a hemisphere and the intersection of hemispheres is a convex region of
/// T², so the kernel is computed as one, with exact homogeneous points: start from the closed
/// front hemisphere (its boundary Ω as four quarter arcs) and cut it by one edge line after the
/// other, keeping the left side. A cut point is the meet of two lines, so coordinates never
/// grow beyond degree 4 in the input. Points at infinity are ordinary points here, which is
/// what makes the unbounded case free: a polygon with vertices on Ω (a wedge, a half-plane) may
/// have a kernel that reaches Ω, and its corners there are points of Ω, with edges along Ω.
///
/// **Running time: O(n) cuts, O(n²) climbs.** Cutting by scanning every corner costs O(k) for a
/// region of k corners, Θ(n²) on a convex polygon. But the edge ending at v_i bounds the region
/// R on its left, so from v_i the region is seen within half a turn, between two tangent
/// corners F (clockwise) and L; the next cut line passes through v_i, so R has a corner right
/// of it iff F or L is (or both lie on it and R is on its right, half a turn wide). A cut then
/// walks from that corner over the corners it removes only: every corner is created once (at
/// most three per cut) and removed once, so the cuts cost O(n) in all. F and L are kept from one
/// vertex to the next and climbed to the new tangents, one corner a step; a climb takes at most
/// as many steps as R has corners, so the climbs cost O(n²), and that is all this code proves.
/// They are **not** O(n) on every simple polygon: a band that first winds round an m-gon and then
/// spirals T more turns round the region, three vertices a turn, sends both fingers round all m
/// corners every turn, Θ(m·T) steps (measured: bench/bench_polygon_kernel.cpp, BM_KernelSpiral,
/// about 0.13 µs a step). Lee and Preparata's O(n) (1979) needs bookkeeping for such winding
/// that this climb does not do; on convex and star polygons the time is measured linear
/// (chapter 07, §5). On a polygon that is not simple the answer is still the intersection of
/// the half-planes, exactly; only the time bound may be lost.

#include <algorithm>
#include <cstddef>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

#include "t2/kernel/error.hpp"
#include "t2/kernel/lexicographic.hpp"
#include "t2/kernel/line.hpp"
#include "t2/kernel/orient.hpp"
#include "t2/kernel/point.hpp"
#include "t2/kernel/polygon.hpp"

namespace t2 {

/// The kernel of a polygon: a convex region of the closed front hemisphere of T².
struct PolygonKernel {
  /// The corners, counter-clockwise (points of Ω where the kernel is unbounded); empty when the
  /// kernel is empty, one point or two (a segment) when it is degenerate.
  std::vector<ExactPoint> vertices;
  /// `edges[k]` is the line from `vertices[k]` to `vertices[k + 1]`, the kernel on its left (Ω
  /// for an edge along Ω). Empty for a kernel of one point.
  std::vector<ExactLine> edges;
  /// True when the kernel has no point.
  bool empty() const { return vertices.empty(); }
  /// True when no corner lies on Ω.
  bool bounded() const {
    for (const auto& v : vertices)
      if (v.w() == 0) return false;
    return true;
  }
};

namespace detail {

// One edge of a region: it starts at `start` and runs along `line`, the region on its left.
struct RegionEdge {
  ExactPoint start;
  ExactLine line;
};

inline ExactPoint cross_point(const ExactLine& l, const ExactPoint& p) {  // l × p, a point of l
  return ExactPoint(Integer(l.X() * p.y() - l.Y() * p.x()), Integer(l.Y() * p.w() - l.W() * p.y()),
                    Integer(l.W() * p.x() - l.X() * p.w()));
}

inline Integer value(const ExactLine& l, const ExactPoint& p) { return l.W() * p.w() + l.X() * p.x() + l.Y() * p.y(); }

// For x, y on l: positive when y lies less than half a turn ahead of x along l, zero when y = ¬x.
inline Integer ahead(const ExactLine& l, const ExactPoint& x, const ExactPoint& y) {
  const ExactPoint m = cross_point(l, x);  // the point 90° ahead of x along l
  return m.w() * y.w() + m.x() * y.x() + m.y() * y.y();
}

// The point where the edge a → b (on line L, ℓ·a and ℓ·b of opposite signs) crosses ℓ: the meet
// of L and ℓ, with the sign of |ℓ·a| b + |ℓ·b| a, the positive combination of a and b on ℓ.
inline ExactPoint crossing(const ExactLine& L, const ExactLine& l, const ExactPoint& a, const ExactPoint& b) {
  const Integer la = value(l, a), lb = value(l, b);
  const ExactPoint m = meet(L, l);
  const Integer dot = (la * b.w() - lb * a.w()) * m.w() + (la * b.x() - lb * a.x()) * m.x() +
                      (la * b.y() - lb * a.y()) * m.y();  // times sign(ℓ·a): positive weights
  return (dot > 0) == (la > 0) ? m : antipode(m);
}

// The region under construction: its corners as a circular doubly linked list (Lee and
// Preparata's list, always closed here: an unbounded region is a bounded one of T² reaching Ω).
// `line` is the edge from the corner to the next one, the region on its left.
struct KernelCorner {
  ExactPoint p;
  ExactLine line;
  std::size_t prev = 0, next = 0;
};

struct KernelRegion {
  std::vector<KernelCorner> c;  // dead corners stay in the vector, unlinked
  std::size_t any = 0;          // a live corner
  std::size_t F = 0, L = 0;     // the two tangent corners seen from the current vertex

  std::size_t add(ExactPoint p, ExactLine l) {
    c.push_back({std::move(p), std::move(l)});
    return c.size() - 1;
  }
  void link(std::size_t a, std::size_t b) { c[a].next = b, c[b].prev = a; }
};

// Where q lies as seen from v, a point of the line m with R on m's left: R's points are seen
// within half a turn, from m's own direction (rank 0: q on m, ahead of v) counter-clockwise to
// the opposite one (rank 2: q on m, behind v); rank 1 is strictly between, where orient orders
// them. (For v on Ω, "ahead" is along m's orientation, and two points of Ω strictly left of m
// are seen in one direction: orient, zero for them, is right to tie them.) Rank -1: q is v or
// ¬v, which have no direction from v (both on m: compared only there).
inline int rank_from(const ExactPoint& v, const ExactLine& m, const ExactPoint& q) {
  if (side(m, q) != 0) return 1;
  if (q == v || q == antipode(v)) return -1;
  // (v ∨ q)·m = det |v; q; m|, positive when v ∨ q has m's direction
  return orient(v, q, dual(m)) > 0 ? 0 : 2;
}

// Moves the finger f to the corner of R extreme as seen from v (a point of m, R left of m),
// clockwise (turn = -1, Lee and Preparata's F: every corner at or counter-clockwise of v → F)
// or counter-clockwise (turn = +1, their L). R is convex and seen within half a turn, so the
// directions of its corners rise and fall once along its boundary: a climb to a strictly
// better neighbour ends at the extreme. The corners v and ¬v have no direction from v: the
// finger leaves them first (a climb never enters them). The finger's rank is kept, so each
// step ranks the neighbours only.
inline void climb(KernelRegion& R, const ExactPoint& v, const ExactLine& m, std::size_t& f, int turn) {
  int rf = rank_from(v, m, R.c[f].p);
  for (std::size_t k = 0; rf < 0 && k < R.c.size(); ++k) rf = rank_from(v, m, R.c[f = R.c[f].next].p);
  //> kernel-climb
  // x is strictly further than f in the sense of turn, as seen from v; rx its rank
  const auto better = [&](std::size_t x, int& rx) {
    const ExactPoint &p = R.c[f].p, &q = R.c[x].p;
    if ((rx = rank_from(v, m, q)) < 0) return false;  // x is v or ¬v
    const int s = rf != rx ? rx - rf : rf == 1 ? static_cast<int>(orient(v, p, q)) : 0;
    return s * turn > 0;
  };
  for (std::size_t steps = 0; steps <= R.c.size(); ++steps) {
    int r = 0;
    if (better(R.c[f].next, r)) f = R.c[f].next, rf = r;
    else if (better(R.c[f].prev, r)) f = R.c[f].prev, rf = r;
    else return;
  }
  //< kernel-climb
  throw std::logic_error("polygon kernel: a tangent climb went around the region");  // never
}

// A corner of R strictly right of l, a line through the current vertex v, or none (R.c.size()).
// With F and L the tangent corners from v: if both are left of or on l, so is every corner
// (their directions span at most half a turn from F counter-clockwise to L), unless both are on
// l and R lies on its right, half a turn wide: then a corner next to the run on l is right of it.
inline std::size_t removed_corner(const KernelRegion& R, const ExactLine& l) {
  for (std::size_t f : {R.F, R.L})
    if (side(l, R.c[f].p) < 0) return f;
  for (std::size_t f : {R.F, R.L})
    for (bool forward : {true, false}) {
      std::size_t k = f;
      for (std::size_t steps = 0; steps < R.c.size(); ++steps) {
        k = forward ? R.c[k].next : R.c[k].prev;
        const Sign s = side(l, R.c[k].p);
        if (s < 0) return k;
        if (s > 0 || k == f) break;
      }
    }
  return R.c.size();
}

// R cut by the closed half-plane left of l, given a corner s strictly right of l: the run of
// corners right of l around s is unlinked, and the points where R's boundary leaves and comes
// back across l are linked in its place. False when every corner is right of l (R is empty).
inline bool cut(KernelRegion& R, const ExactLine& l, std::size_t s) {
  //> kernel-cut
  const auto right = [&](std::size_t k) { return side(l, R.c[k].p) < 0; };
  std::size_t r = s, t = s;  // the run r … t right of l
  while (right(R.c[t].next)) {
    t = R.c[t].next;
    if (t == s) return false;  // every corner: R is empty
  }
  while (right(R.c[r].prev)) r = R.c[r].prev;
  const std::size_t a = R.c[r].prev, b = R.c[t].next;  // kept: left of l or on it
  std::size_t x = a, y = b;  // where the boundary leaves across l and comes back
  if (side(l, R.c[a].p) > 0) {
    x = R.add(crossing(R.c[a].line, l, R.c[a].p, R.c[r].p), l);
    R.link(a, x);
  } else {
    R.c[a].line = l;
  }
  if (side(l, R.c[b].p) > 0) {
    y = R.add(crossing(R.c[t].line, l, R.c[t].p, R.c[b].p), R.c[t].line);
    R.link(y, b);
  }
  if (x == y) {  // one corner on l is left: R is that point
    R.link(x, x);
  } else if (R.c[x].p == R.c[y].p) {  // R was a segment, l crosses it: one corner, not two
    R.c[x].line = R.c[y].line;
    R.link(x, b);
    y = x;
  } else if (ahead(l, R.c[x].p, R.c[y].p) <= 0) {
    const std::size_t m = R.add(cross_point(l, R.c[x].p), l);  // half a turn along l: add
    R.link(x, m), R.link(m, y);                                // the point 90° along it
  } else {
    R.link(x, y);
  }
  //< kernel-cut
  // The tangent corners seen from v, if cut away, become the ends of the new edge along l:
  // F the farther one ahead along l, L the one behind.
  for (std::size_t k = r;; k = R.c[k].next) {
    if (k == R.F) R.F = y;
    if (k == R.L) R.L = x;
    if (k == t) break;
  }
  R.any = x;
  return true;
}

}  // namespace detail

/// The kernel of the polygon P (vertices on the front side or on Ω, the interior on the left
/// of its edges; a front-only polygon given clockwise is read backwards): the intersection of
/// the closed half-planes left of its edge lines, within the closed front hemisphere (file
/// comment). Exact (big-integer homogeneous coordinates). Repeated consecutive vertices are
/// dropped. Throws `BadInput` for fewer than three distinct vertices, a back-side vertex, two
/// consecutive antipodal vertices, or an edge that runs clockwise along Ω.
inline PolygonKernel polygon_kernel(std::span<const Point> P) {
  std::vector<Point> V;
  for (const Point& p : P) {
    if (p.w() < 0) throw BadInput("polygon kernel: the vertex " + to_string(p) + " is on the back side");
    if (V.empty() || !(V.back() == p)) V.push_back(p);
  }
  while (V.size() > 1 && V.back() == V.front()) V.pop_back();
  if (V.size() < 3) throw BadInput("polygon kernel: a polygon needs three distinct vertices");
  bool proper = true;
  for (const Point& p : V) proper = proper && p.w() > 0;
  if (proper && orientation(V) < 0) std::reverse(V.begin(), V.end());
  std::vector<ExactPoint> E;
  for (std::size_t i = 0; i < V.size(); ++i) {
    const Point& a = V[i];
    const Point& b = V[(i + 1) % V.size()];
    if (a == antipode(b)) throw BadInput("polygon kernel: consecutive vertices are antipodal");
    if (a.w() == 0 && b.w() == 0 && orient(Point(1, 0, 0), a, b) < 0)
      throw BadInput("polygon kernel: the edge from " + to_string(a) + " to " + to_string(b) +
                     " runs clockwise along Omega (the inside would be the back side)");
    E.push_back(to_exact(V[i]));
  }
  //> kernel
  // the closed front hemisphere: Ω in four quarters
  detail::KernelRegion R;
  const ExactPoint X(0, 1, 0), Y(0, 0, 1);
  for (const ExactPoint& q : {X, Y, antipode(X), antipode(Y)}) R.add(q, omega<Integer>());
  for (std::size_t k = 0; k < 4; ++k) R.link(k, (k + 1) % 4);
  ExactLine m = omega<Integer>();  // the last cut's line: R is on its left
  for (std::size_t i = 0; i < E.size(); ++i) {
    const ExactLine l = join(E[i], E[(i + 1) % E.size()]);
    std::size_t s = R.c.size();  // a corner right of l, if any
    if (i == 0) {  // the hemisphere has no tangents: look at its four corners
      for (std::size_t k = 0; k < 4; ++k)
        if (side(l, R.c[k].p) < 0) s = k;
    } else {  // E[i] is on m: R is seen from it within half a turn
      detail::climb(R, E[i], m, R.F, -1);
      detail::climb(R, E[i], m, R.L, +1);
      s = detail::removed_corner(R, l);
    }
    if (s < R.c.size() && !detail::cut(R, l, s)) return {};  // empty
    m = l;
  }
  //< kernel
  // Corners only: drop a corner between two edges on one line, if the edge stays under π (one
  // pass, from a corner whose edges lie on two lines).
  std::size_t k0 = R.any;
  for (std::size_t k = R.any;;) {
    if (!(R.c[R.c[k].prev].line == R.c[k].line)) {
      k0 = k;
      break;
    }
    if ((k = R.c[k].next) == R.any) break;
  }
  std::vector<detail::RegionEdge> C;
  for (std::size_t k = k0;;) {
    const std::size_t next = R.c[k].next;
    if (C.empty() || !(C.back().line == R.c[k].line) ||
        detail::ahead(C.back().line, C.back().start, R.c[next].p) <= 0)
      C.push_back({R.c[k].p, R.c[k].line});
    if ((k = next) == k0) break;
  }
  // Start at the least corner in the wxy order (lexicographic.hpp): one answer per region.
  std::size_t first = 0;
  for (std::size_t k = 1; k < C.size(); ++k)
    if (compare_lexicographic(C[k].start, C[first].start) < 0) first = k;
  std::rotate(C.begin(), C.begin() + static_cast<std::ptrdiff_t>(first), C.end());
  PolygonKernel K;
  for (const auto& e : C) K.vertices.push_back(e.start), K.edges.push_back(e.line);
  if (K.vertices.size() == 1) K.edges.clear();
  return K;
}

}  // namespace t2
