#pragma once
/// @file delaunay_recorder.hpp
/// @brief A kernel for `delaunay_with` (triangulation/delaunay.hpp) that records the insertions,
/// the flips and, at the debugging level, every in-circle test, as `Step`s in input indices.
///
/// `delaunay_with` builds on a copy of the points in the order of `spatial_order(input)` and
/// calls the hooks with vertex indices of that copy; the recorder maps them back through the
/// same order (vertex k is input point order[k]). The in-circle hook receives references into
/// the copy, so the recorder recovers their indices from their addresses.
///
/// A kernel with `no_circle = true` answers every in-circle test "outside": then the only flips
/// are those that add the hull edges a new point sees, and the result is the plain incremental
/// triangulation (insert in the triangle that holds the point, or join it to the hull edges it
/// sees), not the Delaunay one. `t2 animate triangulate` shows that one.
///
/// Only front input is recorded: for other input `delaunay_with` triangulates each side apart
/// (delaunay_t2.hpp) and calls the hooks with the sides' own numbering; the recorder then
/// records nothing (`recording()` is false), and `t2 animate` refuses such input.
///
/// Equal points are one vertex: the recorder names it by the smallest of their indices, as the
/// result does.
///
/// Depths: the first triangle, the insertions and the flips are lecture steps; the in-circle
/// tests are debugging steps. Each step holds every finite triangle so far.

#include <algorithm>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "t2/kernel/incircle.hpp"
#include "t2/kernel/lexicographic.hpp"
#include "t2/kernel/orient.hpp"
#include "t2/trace/recording.hpp"
#include "t2/triangulation/spatial_sort.hpp"
#include "t2/triangulation/triangulation.hpp"

namespace t2::trace {

/// A `delaunay_with` kernel with the library's exact predicates that records the steps (see
/// the file comment). Copies share the recording: `delaunay_with` takes its kernel by value.
class DelaunayRecorder {
 public:
  using Index = Triangulation::Index;  ///< the triangulation's indices

  /// @param input the points that will be given to `delaunay_with` (a view is kept)
  /// @param out where the steps go
  /// @param no_circle answer every in-circle test "outside" (the plain incremental triangulation)
  DelaunayRecorder(std::span<const Point> input, Recording& out, bool no_circle = false)
      : order_(spatial_order(input)), out_(&out), no_circle_(no_circle),
        front_(std::all_of(input.begin(), input.end(), [](const Point& p) { return p.w() > 0; })) {
    // Equal points are one vertex, named by the smallest index (delaunay.hpp renames a vertex
    // when a duplicate of smaller index arrives, and calls no hook): name them so from the start.
    std::vector<std::size_t> by_xy(input.size()), smallest(input.size());
    for (std::size_t k = 0; k < input.size(); ++k) by_xy[k] = k;
    std::sort(by_xy.begin(), by_xy.end(), [&](std::size_t a, std::size_t b) {
      const Sign s = t2::compare_xy(input[a], input[b]);
      return s != ZERO ? s < 0 : a < b;
    });
    for (std::size_t k = 0; k < by_xy.size(); ++k)
      smallest[by_xy[k]] = k > 0 && t2::compare_xy(input[by_xy[k - 1]], input[by_xy[k]]) == ZERO
                               ? smallest[by_xy[k - 1]] : by_xy[k];
    for (auto& v : order_) v = static_cast<std::uint32_t>(smallest[v]);
  }

  /// False when the input has points off the front side: then nothing is recorded.
  bool recording() const { return front_; }

  /// Exact orientation of three points.
  static Sign orient(const Point& p, const Point& q, const Point& r) { return t2::orient(p, q, r); }
  /// Exact lexicographic comparison of Cartesian coordinates.
  static Sign compare_xy(const Point& p, const Point& q) { return t2::compare_xy(p, q); }

  /// The exact in-circle test (or NEGATIVE with `no_circle`), recorded at the debugging level.
  Sign in_circle(const Point& a, const Point& b, const Point& c, const Point& d) const {
    const Sign s = no_circle_ ? NEGATIVE : t2::in_circle(a, b, c, d);
    if (tr_ == nullptr || no_circle_ || !front_) return s;
    const std::size_t ia = input_index(a), ib = input_index(b), ic = input_index(c), id = input_index(d);
    Step st = state("in-circle", Depth::debugging, "triangles so far");
    st.text = "Is " + point_name(id) + " inside the circle through " + point_name(ia) + ", " + point_name(ib) + ", " +
              point_name(ic) + "? " +
              (s > 0   ? "Yes: the edge it faces is not locally Delaunay and will flip."
               : s < 0 ? "No: the edge it faces stays."
                       : "It lies on the circle: the symbolic perturbation decides.");
    st.points = {id};
    st.touched = {{ia, ib, ic}};
    st.circle = {ia, ib, ic};
    out_->add(std::move(st));
    return s;
  }

  /// Hook: vertex v (of the triangulation's copy) has just been inserted, before its flips.
  void inserted(const Triangulation& tr, Index v) {
    if (!front_) return;
    tr_ = &tr;
    const std::size_t iv = order_[v];
    if (first_) start(tr, v);
    Step st = state("insert", Depth::lecture, "triangles around the new point");
    bool outside = false;
    for (Index t = 0; t < tr.size(); ++t)
      if (tr.slot(t, v) >= 0) {
        if (tr.is_infinite(t)) outside = true;
        else st.touched.push_back(tri(tr, t));
      }
    st.text = point_name(iv) +
              (outside ? " lies outside the hull: it is joined to the hull edge it sees first."
                       : " is located (by the walk) in a triangle or on an edge and joined to its corners.") +
              " Then every edge opposite " + point_name(iv) + " is tested, and flipped when " +
              (no_circle_ ? point_name(iv) + " sees it as a hull edge from outside." : "it is not locally Delaunay.");
    st.points = {iv};
    out_->add(std::move(st));
  }

  /// Hook: the edge opposite vertex 0 of t has just been flipped; t and u are the new triangles.
  void flipped(const Triangulation& tr, Index t, Index u) {
    if (!front_) return;
    const Index pv = tr.vertex(t, 0), q = tr.vertex(t, 1), d = tr.vertex(t, 2), r = tr.vertex(u, 2);
    Step st = state("flip", Depth::lecture, "triangles touched by the flip");
    for (Index x : {t, u})
      if (!tr.is_infinite(x)) st.touched.push_back(tri(tr, x));
    const std::size_t ip = order_[pv];
    if (st.touched.size() == 2) {
      st.text = point_name(ip) + " lies inside the circle of " + point_name(order_[q]) + ", " + point_name(order_[r]) +
                ", " + point_name(order_[d]) + ": the edge " + point_name(order_[q]) + " " + point_name(order_[r]) +
                " is not locally Delaunay and flips to " + point_name(ip) + " " + point_name(order_[d]) + ".";
      st.edges = {{ip, order_[d]}};
    } else if (st.touched.size() == 1) {
      const Tri& f = st.touched[0];
      st.text = point_name(ip) + " sees the hull edge " + point_name(f[1]) + " " + point_name(f[2]) +
                " from outside: the flip adds the triangle " + point_name(f[0]) + " " + point_name(f[1]) + " " +
                point_name(f[2]) + " and the hull grows.";
      st.edges = {{f[1], f[2]}};
    } else {
      st.text = "A flip between two infinite triangles at " + point_name(ip) + ".";
    }
    st.points = {ip};
    out_->add(std::move(st));
  }

  /// The finite triangles of `tr` in input indices, each rotated to start at its smallest index,
  /// sorted (the form of `Triangulation::finite_triangles` of the result, sorted).
  std::vector<Tri> finite(const Triangulation& tr) const {
    std::vector<Tri> out;
    for (Index t = 0; t < tr.size(); ++t)
      if (!tr.is_infinite(t)) out.push_back(tri(tr, t));
    std::sort(out.begin(), out.end());
    return out;
  }

 private:
  Tri tri(const Triangulation& tr, Index t) const {
    Tri x{order_[tr.vertex(t, 0)], order_[tr.vertex(t, 1)], order_[tr.vertex(t, 2)]};
    std::rotate(x.begin(), std::min_element(x.begin(), x.end()), x.end());
    return x;
  }

  std::size_t input_index(const Point& a) const {
    const std::ptrdiff_t k = &a - tr_->points().data();
    return k >= 0 && static_cast<std::size_t>(k) < order_.size() ? order_[static_cast<std::size_t>(k)] : 0;
  }

  Step state(const char* kind, Depth d, const char* structure) const {
    Step st;
    st.kind = kind;
    st.depth = d;
    st.structure = structure;
    st.triangles = finite(*tr_);
    return st;
  }

  // The first triangle, made before the first hook: the vertices other than v.
  void start(const Triangulation& tr, Index v) {
    first_ = false;
    std::vector<Index> vs;
    for (Index t = 0; t < tr.size(); ++t)
      for (int i = 0; i < 3; ++i) {
        const Index x = tr.vertex(t, i);
        if (x != v && x != Triangulation::infinite && std::find(vs.begin(), vs.end(), x) == vs.end()) vs.push_back(x);
      }
    if (vs.size() != 3) return;
    if (t2::orient(tr.point(vs[0]), tr.point(vs[1]), tr.point(vs[2])) < 0) std::swap(vs[1], vs[2]);
    Tri f{order_[vs[0]], order_[vs[1]], order_[vs[2]]};
    std::rotate(f.begin(), std::min_element(f.begin(), f.end()), f.end());
    Step st;
    st.kind = "start";
    st.structure = "triangles so far";
    st.triangles = {f};
    st.touched = {f};
    st.points = {f[0], f[1], f[2]};
    st.text = "The first triangle: " + point_name(f[0]) + ", " + point_name(f[1]) + ", " + point_name(f[2]) +
              " (the first points, in the " +
              "BRIO–Hilbert insertion order, that are not collinear). Its outside is three infinite triangles.";
    out_->add(std::move(st));
  }

  std::vector<std::uint32_t> order_;
  Recording* out_;
  bool no_circle_;
  bool front_;  // every input point is on the front side (else nothing is recorded)
  const Triangulation* tr_ = nullptr;
  bool first_ = true;
};

}  // namespace t2::trace
