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
/// other, keeping the left side (Sutherland–Hodgman). A cut point is the meet of two lines, so
/// coordinates never grow beyond degree 4 in the input. Points at infinity are ordinary points
/// here, which is what makes the unbounded case free: a polygon with vertices on Ω (a wedge, a
/// half-plane) may have a kernel that reaches Ω, and its vertices there are points of Ω, with
/// edges along Ω between them. Each cut costs O(k) for a region of k vertices: O(n k) in all.
/// Lee and Preparata reach O(n) by starting at a reflex vertex and keeping the two tangent
/// points F and L from the current vertex, so that each cut scans only the part it removes;
/// the answer is the same region.

#include <algorithm>
#include <cstddef>
#include <span>
#include <string>
#include <vector>

#include "t2/error.hpp"
#include "t2/line.hpp"
#include "t2/point.hpp"
#include "t2/polygon.hpp"

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

// The region R cut by the closed half-plane left of l (Sutherland–Hodgman on its boundary).
inline void cut(std::vector<RegionEdge>& R, const ExactLine& l) {
  const std::size_t m = R.size();
  std::vector<Sign> s(m);
  bool out_side = false;
  for (std::size_t k = 0; k < m; ++k) out_side = (s[k] = sign_of(value(l, R[k].start))) < 0 || out_side;
  if (!out_side) return;
  //> kernel-cut
  std::vector<RegionEdge> out;
  for (std::size_t k = 0; k < m; ++k) {
    const RegionEdge& a = R[k];
    const ExactPoint& b = R[(k + 1) % m].start;
    const Sign sa = s[k], sb = s[(k + 1) % m];
    // kept; leaves along l
    if (sa >= 0) out.push_back({a.start, sa == 0 && sb < 0 ? l : a.line});
    // leaves: along l
    if (sa > 0 && sb < 0) out.push_back({crossing(a.line, l, a.start, b), l});
    // comes back
    if (sa < 0 && sb > 0) out.push_back({crossing(a.line, l, a.start, b), a.line});
  }
  // an edge along l of half a turn: add the point 90° along it
  for (std::size_t k = 0; k < out.size() && out.size() > 1; ++k) {
    const ExactPoint& x = out[k].start;
    const ExactPoint& y = out[(k + 1) % out.size()].start;
    if (out[k].line == l && !(x == y) && ahead(l, x, y) <= 0)
      out.insert(out.begin() + static_cast<std::ptrdiff_t>(k + 1),
                 RegionEdge{cross_point(l, x), l});
  }
  //< kernel-cut
  R = std::move(out);
}

}  // namespace detail

/// The kernel of the polygon P (vertices on the front side or on Ω, the interior on the left
/// of its edges; a front-only polygon given clockwise is read backwards): the intersection of
/// the closed half-planes left of its edge lines, within the closed front hemisphere (file
/// comment). Exact (big-integer homogeneous coordinates). Repeated consecutive vertices are
/// dropped. Throws `BadInput` for fewer than three distinct vertices, a back-side vertex, or
/// two consecutive antipodal vertices.
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
  //> kernel
  // the closed front hemisphere: Ω in four quarters
  const ExactPoint X(0, 1, 0), Y(0, 0, 1);
  std::vector<detail::RegionEdge> R{{X, omega<Integer>()},
                                    {Y, omega<Integer>()},
                                    {antipode(X), omega<Integer>()},
                                    {antipode(Y), omega<Integer>()}};
  for (std::size_t i = 0; i < V.size() && !R.empty(); ++i) {
    const Point& a = V[i];
    const Point& b = V[(i + 1) % V.size()];
    if (a == antipode(b))
      throw BadInput("polygon kernel: consecutive vertices are antipodal");
    detail::cut(R, join(to_exact(a), to_exact(b)));
  }
  //< kernel
  // Corners only: drop a vertex between two edges on one line, if the edge stays under π.
  for (bool changed = true; changed && R.size() > 2;) {
    changed = false;
    for (std::size_t k = 0; k < R.size() && R.size() > 2; ++k) {
      const auto& prev = R[(k + R.size() - 1) % R.size()];
      const auto& next = R[(k + 1) % R.size()];
      if (prev.line == R[k].line &&
          detail::ahead(prev.line, prev.start, next.start) > 0) {
        R.erase(R.begin() + static_cast<std::ptrdiff_t>(k));
        changed = true;
      }
    }
  }
  PolygonKernel K;
  for (const auto& e : R) K.vertices.push_back(e.start), K.edges.push_back(e.line);
  if (K.vertices.size() == 1) K.edges.clear();
  return K;
}

}  // namespace t2
