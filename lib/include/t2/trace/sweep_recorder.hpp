#pragma once
/// @file sweep_recorder.hpp
/// @brief A hook (trace/hook.hpp) for `triangulate` (triangulation/triangulate.hpp) that
/// records the sweep of chapter 09 as `Step`s: `t2 animate triangulate` on front points.
///
/// `triangulate` builds on the input's own indices (no reordering) and reports which event each
/// is: the first triangle, a point on its first edge, a swept point, a flip, the end. The points
/// are swept in (x, y) order; equal points are one vertex (the smallest index) and are not
/// reported.
///
/// Depths (seed 003's levels, as the chapter teaches the sweep): at the lecture level one step
/// per point — the first triangle, then each point with its new fan, the triangles it has made
/// once its flips are done; at the debugging level also the point joined to the one hull edge
/// it is put against, and each flip of Algorithm 9's step 35, a hull edge it also sees turned
/// into a triangle. Every step holds every finite triangle so far and the hull so far (closed,
/// counter-clockwise), so a player can jump to it.
///
/// The last point's fan is recorded when the sweep reports that it is done.

#include <algorithm>
#include <array>
#include <cstddef>
#include <map>
#include <span>
#include <string>
#include <vector>

#include "t2/trace/hook.hpp"
#include "t2/trace/recording.hpp"
#include "t2/triangulation/triangulation.hpp"

namespace t2::trace {

/// A `triangulate` hook that records the steps of the sweep (see the file comment).
class SweepRecorder {
 public:
  using Index = Triangulation::Index;  ///< the triangulation's indices

  /// @param out where the steps go
  explicit SweepRecorder(Recording& out) : out_(&out) {}
  /// Not copied: `triangulate` takes its hook by reference, and a copy would split the steps.
  SweepRecorder(const SweepRecorder&) = delete;
  /// Not copied (see the copy constructor).
  SweepRecorder& operator=(const SweepRecorder&) = delete;

  /// The hook.
  void operator()(const Report& r) {
    switch (r.event) {
      case Event::start: return start(*r.tr, r.at);
      case Event::on_edge: return on_edge(*r.tr, static_cast<Index>(r.at[0]));
      case Event::insert: return insert(*r.tr, static_cast<Index>(r.at[0]));
      case Event::flip: return flipped(*r.tr, r.faces[0], r.faces[1]);
      case Event::done: return finish();
      default: return;
    }
  }

 private:
  void start(const Triangulation& tr, const std::array<std::size_t, 4>& at) {
    Step st = state(tr, "start", Depth::lecture, "hull so far");
    const Tri f = st.triangles.at(0);
    st.touched = {f};
    st.points = {at[0], at[1], at[2]};
    st.text = "The sweep takes the points in (x, y) order. The first triangle: " + point_name(f[0]) + ", " +
              point_name(f[1]) + ", " + point_name(f[2]) + " (the smallest two points and the first point off "
              "their line).";
    out_->add(std::move(st));
  }

  void on_edge(const Triangulation& tr, Index v) {
    Step st = state(tr, "insert", Depth::lecture, "hull so far");
    st.points = {v};
    st.touched = fan(tr, v);
    // a point on the first edge: joined to both triangles, no flip
    st.text = point_name(v) +
              " lies on the first edge, between the smallest two points: it splits the edge, and the triangle "
              "on it, in two.";
    out_->add(std::move(st));
  }

  void insert(const Triangulation& tr, Index v) {
    finish();  // the fan of the point before
    Step st = state(tr, "insert", Depth::debugging, "hull so far");
    st.points = {v};
    st.touched = fan(tr, v);
    const Tri& t = st.touched.at(0);
    st.edges = {{t[0] == v ? t[1] : t[0], t[2] == v ? t[1] : t[2]}};
    st.text = point_name(v) +
              ", the next point in (x, y) order, lies outside the hull of the points before it and sees the hull "
              "edge " +
              point_name(st.edges[0][0]) + " " + point_name(st.edges[0][1]) +
              " at the last point: joined to it, one triangle. "
              "Next, step 35: the hull edges next to it that it also sees.";
    out_->add(std::move(st));
    flips_ = 0;
    pending_ = fan_step(tr, v);
  }

  // The edge opposite vertex 0 of t has just been flipped; t and u are the new triangles.
  void flipped(const Triangulation& tr, Index t, Index u) {
    const Index v = tr.vertex(t, 0);
    Step st = state(tr, "flip", Depth::debugging, "hull so far");
    for (Index x : {t, u})
      if (!tr.is_infinite(x)) st.touched.push_back(tri(tr, x));
    st.points = {v};
    if (st.touched.size() == 1) {
      const Tri& f = st.touched[0];
      st.edges = {{f[0] == v ? f[1] : f[0], f[2] == v ? f[1] : f[2]}};
      st.text = point_name(v) + " also sees the hull edge " + point_name(st.edges[0][0]) + " " +
                point_name(st.edges[0][1]) + " from outside too: step 35 flips it into the triangle " +
                point_name(f[0]) + " " + point_name(f[1]) + " " + point_name(f[2]) + ", and the reflex angle at " +
                point_name(v) + " is gone.";
    }
    out_->add(std::move(st));
    ++flips_;
    pending_ = fan_step(tr, v);
  }

  // Records the fan of the last swept point, if it is not recorded yet (at the next insert,
  // and at the end).
  void finish() {
    if (pending_.kind.empty()) return;
    const std::size_t n = pending_.touched.size();
    pending_.text = point_name(pending_.points.at(0)) + " is a hull vertex now; its fan: " + std::to_string(n) +
                    " new triangle" + (n == 1 ? "" : "s") + " (" + std::to_string(flips_) + " hull edge" +
                    (flips_ == 1 ? "" : "s") + " flipped away by step 35).";
    out_->add(std::move(pending_));
    pending_ = Step();
  }

  static Tri tri(const Triangulation& tr, Index t) {
    Tri x{tr.vertex(t, 0), tr.vertex(t, 1), tr.vertex(t, 2)};
    std::rotate(x.begin(), std::min_element(x.begin(), x.end()), x.end());
    return x;
  }

  // The finite triangles at v, sorted.
  static std::vector<Tri> fan(const Triangulation& tr, Index v) {
    std::vector<Tri> out;
    for (Index t = 0; t < tr.size(); ++t)
      if (!tr.is_infinite(t) && tr.slot(t, v) >= 0) out.push_back(tri(tr, t));
    std::sort(out.begin(), out.end());
    return out;
  }

  // The lecture step of swept point v, its fan, as tr holds it now (the text comes at the end).
  static Step fan_step(const Triangulation& tr, Index v) {
    Step st = state(tr, "fan", Depth::lecture, "hull so far");
    st.points = {v};
    st.touched = fan(tr, v);
    return st;
  }

  // The state after a step: every finite triangle (sorted, smallest index first, as
  // `Triangulation::finite_triangles` gives them) and the hull so far, counter-clockwise.
  static Step state(const Triangulation& tr, const char* kind, Depth d, const char* structure) {
    Step st;
    st.kind = kind;
    st.depth = d;
    st.structure = structure;
    for (const auto& f : tr.finite_triangles()) st.triangles.push_back({f[0], f[1], f[2]});
    std::sort(st.triangles.begin(), st.triangles.end());
    std::map<Index, Index> next;
    for (const auto& [a, b] : tr.hull_edges()) next[a] = b;
    for (Index a = next.empty() ? 0 : next.begin()->first; !next.empty() && st.chain.size() < next.size();
         a = next[a])
      st.chain.push_back(a);
    st.closed = true;
    return st;
  }

  Recording* out_;
  Step pending_;            // the fan of the last swept point, not recorded yet (kind "" when none)
  std::size_t flips_ = 0;   // the flips of that point
};

}  // namespace t2::trace
