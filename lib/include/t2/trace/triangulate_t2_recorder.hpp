#pragma once
/// @file triangulate_t2_recorder.hpp
/// @brief A hook (trace/hook.hpp) for Algorithm 9 on T² (triangulation/insert_t2.hpp) that
/// records its steps as `Step`s: `t2 animate triangulate-t2`, and `t2 animate triangulate` on
/// input with points behind or on Ω.
///
/// The algorithm reports input indices and lends its triangulation with the map from its
/// vertices (positions in the insertion order) to input indices; the recorder reads the faces
/// through that map. Depths (seed 003's levels): at the lecture level the first
/// triangle and then one step per point — in a face, on an edge, merged with an equal vertex,
/// outside the hull with its new fan, or taking the place of v∞ (the hull gone; with the
/// antipodal edge z → ¬z when it is the antipode of a hull vertex); at the debugging level also a
/// point joined to a hull edge it sees, each flip of step 35, each face where the point takes
/// v∞'s place, and each point that has to wait. Every step holds every finite face so far (lunes
/// and flat faces included) and the hull so far (closed, counter-clockwise; empty once the hull
/// is gone), so a player can jump to it, and Euler's formula holds for each.

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <map>
#include <span>
#include <string>
#include <vector>

#include "t2/trace/hook.hpp"
#include "t2/trace/recording.hpp"
#include "t2/triangulation/triangulation.hpp"

namespace t2::trace {

/// A trace of `triangulate_t2` that records its steps (see the file comment).
class TriangulateT2Recorder {
 public:
  using Index = Triangulation::Index;  ///< the triangulation's indices

  /// @param out where the steps go
  explicit TriangulateT2Recorder(Recording& out) : out_(&out) {}
  /// Not copied: a copy would split the steps.
  TriangulateT2Recorder(const TriangulateT2Recorder&) = delete;
  /// Not copied (see the copy constructor).
  TriangulateT2Recorder& operator=(const TriangulateT2Recorder&) = delete;

  /// The hook.
  void operator()(const Report& r) {
    order_ = r.input_of;  // valid while the report is
    const Triangulation& tr = *r.tr;
    const std::size_t v = r.at[0];
    switch (r.event) {
      case Event::start: {
        Step st = state(tr, "start", Depth::lecture);
        st.touched = st.triangles;
        const Tri& f = st.touched.at(0);
        st.points = {f[0], f[1], f[2]};
        st.text = "The points go in a spatial order on the sphere (or in input order). The first triangle: " +
                  point_name(f[0]) + ", " + point_name(f[1]) + ", " + point_name(f[2]) +
                  ", with v∞ beyond each of its edges.";
        out_->add(std::move(st));
        return;
      }
      case Event::join: return joined(tr, v, r.faces[0]);
      case Event::flip: return flipped(tr, v, r.faces[0], r.faces[1]);
      case Event::replace: return replaced(tr, v, r.face_list);
      case Event::in_face: case Event::on_edge: case Event::duplicate: case Event::outside:
      case Event::cover: case Event::antipode: case Event::wait: return inserted(tr, r);
      default: return;
    }
  }

 private:
  // p is inserted, merged, or waits.
  void inserted(const Triangulation& tr, const Report& r) {
    Step st = state(tr, "insert", Depth::lecture);
    const std::size_t v = r.at[0];
    st.points = {v};
    st.touched = fan(tr, v);
    switch (r.event) {
      case Event::in_face:
        st.text = point_name(v) + " lies inside a face: it splits it in three.";
        break;
      case Event::on_edge:
        st.text = point_name(v) + " lies inside an edge: the two faces on it split into four.";
        break;
      case Event::duplicate:
        st.kind = "merge";
        st.points = {r.at[0], r.at[1]};
        st.touched.clear();
        st.text = point_name(r.at[0]) + " equals " + point_name(r.at[1]) + ": one vertex, " + point_name(r.at[1]) +
                  " (the smaller index).";
        break;
      case Event::outside:
        st.text = point_name(v) +
                  " lies outside the hull and its antipode too, so the hull survives: joined to every hull edge it "
                  "sees, " +
                  std::to_string(st.touched.size()) + " new triangle" + (st.touched.size() == 1 ? "" : "s") + ".";
        break;
      case Event::cover:
        st.text = point_name(v) +
                  " sees every hull edge: its antipode lies inside the hull. It takes the place of v∞ in every "
                  "infinite face; the faces now cover the sphere and the hull is gone.";
        break;
      case Event::antipode:
        st.text = point_name(v) +
                  " is the antipode of a hull vertex: it takes the place of v∞, and the two faces at the antipodal "
                  "edge are lunes, the edge along the bisector of the hull angle (seed 000, figure 5.18).";
        break;
      default:  // wait
        st.kind = "wait";
        st.depth = Depth::debugging;
        st.touched.clear();
        st.text = point_name(v) +
                  "'s antipode lies inside a hull edge: the face beyond would be bounded by a whole great circle, so " +
                  point_name(v) + " waits until the hull is gone.";
        break;
    }
    out_->add(std::move(st));
  }

  // v, outside the hull, is put into the infinite face of a hull edge; t is its finite face.
  void joined(const Triangulation& tr, std::size_t v, Index t) {
    Step st = state(tr, "join", Depth::debugging);
    st.points = {v};
    st.touched = {tri(tr, t)};
    const Tri& f = st.touched[0];
    st.edges = {{f[0] == v ? f[1] : f[0], f[2] == v ? f[1] : f[2]}};
    st.text = point_name(v) + " lies outside the hull and sees the hull edge " + point_name(st.edges[0][0]) + " " +
              point_name(st.edges[0][1]) +
              ": joined to it. Next, step 35: the hull edges next to it that it also sees.";
    out_->add(std::move(st));
  }

  // A flip of step 35 at v; t and u are the new triangles.
  void flipped(const Triangulation& tr, std::size_t v, Index t, Index u) {
    Step st = state(tr, "flip", Depth::debugging);
    st.points = {v};
    for (Index x : {t, u})
      if (!tr.is_infinite(x)) st.touched.push_back(tri(tr, x));
    st.text = point_name(v) + " also sees the next hull edge: step 35 flips it into a triangle at " +
              point_name(v) + ", and the reflex angle there is gone.";
    out_->add(std::move(st));
  }

  // v has taken v∞'s place in `faces`: one debugging step per face.
  void replaced(const Triangulation& tr, std::size_t v, std::span<const Index> faces) {
    std::size_t k = 0;
    for (Index t : faces) {
      Step st = state(tr, "replace", Depth::debugging);
      st.points = {v};
      st.touched = {tri(tr, t)};
      ++k;
      st.text = "Face " + std::to_string(k) + " of " + std::to_string(faces.size()) + ": " + point_name(v) +
                " takes the place of v∞ in the infinite face of a hull edge, which becomes a finite face.";
      out_->add(std::move(st));
    }
  }

  // A face as input indices, rotated so that its smallest index comes first.
  Tri tri(const Triangulation& tr, Index t) const {
    Tri x{order_[tr.vertex(t, 0)], order_[tr.vertex(t, 1)], order_[tr.vertex(t, 2)]};
    std::rotate(x.begin(), std::min_element(x.begin(), x.end()), x.end());
    return x;
  }

  // The finite faces at input point v, sorted.
  std::vector<Tri> fan(const Triangulation& tr, std::size_t v) const {
    std::vector<Tri> out;
    for (Index t = 0; t < tr.size(); ++t)
      if (!tr.is_infinite(t)) {
        const Tri f = tri(tr, t);
        if (f[0] == v || f[1] == v || f[2] == v) out.push_back(f);
      }
    std::sort(out.begin(), out.end());
    return out;
  }

  // The state after a step: every finite face, sorted, and the hull so far, counter-clockwise.
  Step state(const Triangulation& tr, const char* kind, Depth d) const {
    Step st;
    st.kind = kind;
    st.depth = d;
    st.structure = "hull so far";
    for (Index t = 0; t < tr.size(); ++t)
      if (!tr.is_infinite(t)) st.triangles.push_back(tri(tr, t));
    std::sort(st.triangles.begin(), st.triangles.end());
    std::map<std::size_t, std::size_t> next;
    for (const auto& [a, b] : tr.hull_edges()) next[order_[a]] = order_[b];
    for (std::size_t a = next.empty() ? 0 : next.begin()->first; !next.empty() && st.chain.size() < next.size();
         a = next[a])
      st.chain.push_back(a);
    st.closed = true;
    return st;
  }

  Recording* out_;
  std::span<const std::uint32_t> order_;  // vertex -> input index, of the report being heard
};

}  // namespace t2::trace
