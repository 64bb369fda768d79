#pragma once
/// @file delaunay_recorder.hpp
/// @brief A hook (trace/hook.hpp) for `delaunay_with` (triangulation/delaunay.hpp) that records
/// the first triangle, the insertions, the flips and, at the debugging level, every in-circle
/// test, as `Step`s in input indices.
///
/// The recorder only narrates: the algorithm reports each event with the input indices of its
/// points and lends its triangulation with the map from its vertices (in insertion order) to
/// input indices; the recorder copies the finite triangles through that map. The circle that an
/// in-circle test or a flip speaks of is drawn: its exact centre (`circle_through`, rounded once
/// to doubles) goes into the step's overlay.
///
/// Only front input is traced (`delaunay_with` does not trace its T² assembly): for other input
/// the recorder hears nothing and records nothing.
///
/// Equal points are one vertex: the algorithm names it by the smallest of their indices from
/// the moment it meets the second one (a `duplicate` step); before that the vertex has the index
/// of the point that came first in the insertion order.
///
/// Depths: the first triangle, the insertions, the duplicates and the flips are lecture steps;
/// the in-circle tests are debugging steps. Each step holds every finite triangle so far.

#include <algorithm>
#include <span>
#include <string>
#include <vector>

#include "t2/kernel/circle.hpp"
#include "t2/kernel/error.hpp"
#include "t2/trace/hook.hpp"
#include "t2/trace/overlay.hpp"
#include "t2/trace/recording.hpp"
#include "t2/triangulation/triangulation.hpp"

namespace t2::trace {

/// A `delaunay_with` hook that records the steps (see the file comment).
class DelaunayRecorder {
 public:
  using Index = Triangulation::Index;  ///< the triangulation's indices

  /// @param input the points given to `delaunay_with` (a view is kept: the overlay's circles)
  /// @param out where the steps go
  DelaunayRecorder(std::span<const Point> input, Recording& out) : input_(input), out_(&out) {}

  /// The hook.
  void operator()(const Report& r) {
    switch (r.event) {
      case Event::start: return start(r);
      case Event::insert: return insert(r);
      case Event::duplicate: return duplicate(r);
      case Event::in_circle: return in_circle(r);
      case Event::flip: return flip(r);
      default: return;
    }
  }

 private:
  void start(const Report& r) {
    Step st = state(r, "start", Depth::lecture, "triangles so far");
    const Tri f = rotated({r.at[0], r.at[1], r.at[2]});
    st.touched = {f};
    st.points = {f[0], f[1], f[2]};
    st.text = "The first triangle: " + point_name(f[0]) + ", " + point_name(f[1]) + ", " + point_name(f[2]) +
              " (the first points, in the BRIO–Hilbert insertion order, that are not collinear). Its outside is "
              "three infinite triangles.";
    out_->add(std::move(st));
  }

  void insert(const Report& r) {
    const std::size_t iv = r.at[0];
    Step st = state(r, "insert", Depth::lecture, "triangles around the new point");
    bool outside = false;
    for (Index t = 0; t < r.tr->size(); ++t)
      for (int k = 0; k < 3; ++k)
        if (r.tr->vertex(t, k) != Triangulation::infinite && r.input(r.tr->vertex(t, k)) == iv) {
          if (r.tr->is_infinite(t)) outside = true;
          else st.touched.push_back(tri(r, t));
        }
    st.text = point_name(iv) +
              (outside ? " lies outside the hull: it is joined to the hull edge it sees first."
                       : " is located (by the walk) in a triangle or on an edge and joined to its corners.") +
              " Then every edge opposite " + point_name(iv) + " is tested, and flipped when it is not locally "
              "Delaunay.";
    st.points = {iv};
    out_->add(std::move(st));
  }

  void duplicate(const Report& r) {
    Step st = state(r, "merge", Depth::lecture, "triangles so far");
    st.points = {r.at[0], r.at[1]};
    st.text = point_name(r.at[0]) + " equals " + point_name(r.at[1]) + ": one vertex, " + point_name(r.at[1]) +
              " (the smaller index). No triangle changes.";
    out_->add(std::move(st));
  }

  void in_circle(const Report& r) {
    const std::size_t ia = r.at[0], ib = r.at[1], ic = r.at[2], id = r.at[3];
    Step st = state(r, "in-circle", Depth::debugging, "triangles so far");
    st.text = "Is " + point_name(id) + " inside the circle through " + point_name(ia) + ", " + point_name(ib) + ", " +
              point_name(ic) + "? " +
              (r.tie ? "It lies on the circle: the symbolic perturbation decides " +
                           std::string(r.sign > 0 ? "inside: the edge it faces will flip." : "outside: the edge stays.")
               : r.sign > 0 ? "Yes: the edge it faces is not locally Delaunay and will flip."
                            : "No: the edge it faces stays.");
    st.points = {id};
    st.touched = {rotated({ia, ib, ic})};
    circle(st, {ia, ib, ic});
    out_->add(std::move(st));
  }

  void flip(const Report& r) {
    const Triangulation& tr = *r.tr;
    const Index t = r.faces[0], u = r.faces[1];
    Step st = state(r, "flip", Depth::lecture, "triangles touched by the flip");
    for (Index x : {t, u})
      if (!tr.is_infinite(x)) st.touched.push_back(tri(r, x));
    const std::size_t ip = r.at[0];
    if (st.touched.size() == 2) {
      // t = (p, q, d), u = (p, d, r) after the flip of the edge q r
      const std::size_t q = r.input(tr.vertex(t, 1)), d = r.input(tr.vertex(t, 2)), s = r.input(tr.vertex(u, 2));
      st.text = point_name(ip) + " lies inside the circle of " + point_name(q) + ", " + point_name(s) + ", " +
                point_name(d) + ": the edge " + point_name(q) + " " + point_name(s) +
                " is not locally Delaunay and flips to " + point_name(ip) + " " + point_name(d) + ".";
      st.edges = {{ip, d}};
      circle(st, {q, s, d});
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

  // The circle through three input points, into the overlay (none when they are collinear).
  void circle(Step& st, Tri abc) const {
    try {
      add_circle(st.overlay, t2::circle_through(input_[abc[0]], input_[abc[1]], input_[abc[2]]));
    } catch (const Undefined&) {  // collinear: no circle to draw
    }
  }

  static Tri rotated(Tri x) {
    std::rotate(x.begin(), std::min_element(x.begin(), x.end()), x.end());
    return x;
  }

  static Tri tri(const Report& r, Index t) {
    return rotated({r.input(r.tr->vertex(t, 0)), r.input(r.tr->vertex(t, 1)), r.input(r.tr->vertex(t, 2))});
  }

  // A step holding every finite triangle of the reported triangulation, in input indices,
  // each rotated to start at its smallest index, sorted.
  static Step state(const Report& r, const char* kind, Depth d, const char* structure) {
    Step st;
    st.kind = kind;
    st.depth = d;
    st.structure = structure;
    for (Index t = 0; t < r.tr->size(); ++t)
      if (!r.tr->is_infinite(t)) st.triangles.push_back(tri(r, t));
    std::sort(st.triangles.begin(), st.triangles.end());
    return st;
  }

  std::span<const Point> input_;
  Recording* out_;
};

}  // namespace t2::trace
