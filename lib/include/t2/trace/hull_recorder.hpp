#pragma once
/// @file hull_recorder.hpp
/// @brief A hook (trace/hook.hpp) for the hull algorithms that records every step it is told
/// of as a `Step`: explained in words, with the stack or hull so far, and what to highlight.
///
/// The hull algorithms report events in input indices; this recorder turns each report into a
/// sentence that depends on the algorithm (a pop in Graham's scan is a right turn found, a
/// `consider` in Jarvis's march is a candidate challenged: the march tells the candidate before
/// and after the point and the sign of Δ(u, candidate, point)). It narrates and computes
/// nothing of the algorithm's state.
///
/// Depths: push, pop, vertex and bridge are lecture steps; consider is a debugging step. In the
/// merge, the monotone chains of the two halves are a sub-algorithm, one level deeper (as
/// GeoLab's animation depth grows when an algorithm calls another): their pushes and pops are
/// debugging steps, and the lecture level shows each half's finished hull (a step "half" each,
/// told by the merge: first the positive half's, then the negative half's, built on the
/// antipodes, drawn with the positive one dashed beside it) and then the bridges. When every
/// point lies in one half there is nothing to merge and that half's chain is the whole
/// algorithm: its pushes and pops are then lecture steps, and no "half" step repeats the answer.

#include <algorithm>
#include <cstddef>
#include <limits>
#include <span>
#include <string>
#include <vector>

#include "t2/kernel/point.hpp"
#include "t2/trace/hook.hpp"
#include "t2/trace/recording.hpp"

namespace t2::trace {

/// Which hull algorithm a `HullRecorder` listens to (the wording of its steps).
enum class HullAlgo {
  jarvis,  ///< Jarvis's march (jarvis.hpp)
  graham,  ///< Graham's scan (graham.hpp)
  merge,   ///< the merge of the hemisphere hulls (merge.hpp): monotone chain, then bridges
};

/// A trace for the hull algorithms that records into a `Recording` (see the file comment).
class HullRecorder {
 public:
  static constexpr std::size_t none = std::numeric_limits<std::size_t>::max();  ///< no index

  /// @param algo the algorithm traced
  /// @param P the input points (read once: for the merge, whether they all lie in one half)
  /// @param out where the steps go
  HullRecorder(HullAlgo algo, std::span<const Point> P, Recording& out) : algo_(algo), out_(out) {
    // The merge's chains are a lecture of their own when one half holds every point (the file
    // comment); that is a property of the input, known before the first report.
    const auto positive = [](const Point& p) {  // merge.hpp's split, lexicographic
      return (p.w() != 0 ? sign_of(p.w()) : p.x() != 0 ? sign_of(p.x()) : sign_of(p.y())) > 0;
    };
    if (std::all_of(P.begin(), P.end(), positive)) only_ = 1;
    else if (std::none_of(P.begin(), P.end(), positive)) only_ = 2;
  }

  /// The hook (trace/hook.hpp).
  void operator()(const Report& r) {
    const std::vector<std::size_t> c(r.chain.begin(), r.chain.end());
    const Event step = r.event;
    const std::size_t i = r.at[0];
    switch (algo_) {
      case HullAlgo::jarvis: jarvis(r, c); break;
      case HullAlgo::graham: graham(step, i, c, "stack", "", Depth::lecture); break;
      case HullAlgo::merge:
        if (step == Event::bridge) {
          bridge(i, c);
        } else if (step == Event::positive_half || step == Event::negative_half) {
          half(step == Event::positive_half ? 1 : 2, c);
        } else {
          graham(step, i, c, half_ == 1 ? "chain (positive half)" : "chain (negative half's antipodes)",
                 half_ == 1 ? "Monotone chain of the positive half: "
                            : "Monotone chain of the negative half's antipodes: ",
                 only_ == half_ ? Depth::lecture : Depth::debugging);
        }
        break;
    }
  }

 private:
  void add(const char* kind, Depth d, std::string text, const char* structure, std::vector<std::size_t> chain,
           std::vector<std::size_t> points, std::vector<Edge> edges = {}, bool closed = false) {
    Step s;
    s.kind = kind;
    s.depth = d;
    s.text = std::move(text);
    s.structure = structure;
    s.chain = std::move(chain);
    s.closed = closed;
    s.points = std::move(points);
    s.edges = std::move(edges);
    out_.add(std::move(s));
  }

  // Graham's scan, and the monotone chain inside the merge (the same pushes and pops).
  void graham(Event step, std::size_t i, std::vector<std::size_t> c, const char* structure,
              const std::string& prefix, Depth change = Depth::lecture) {
    const std::size_t n = c.size();
    if (step == Event::consider) {
      current_ = i;
      if (n < 2) {
        add("consider", Depth::debugging,
            prefix + point_name(i) + " comes next; the " + structure + " holds one point, so it " + "will be pushed.",
            structure, c, {i});
      } else {
        add("consider", Depth::debugging,
            prefix + point_name(i) + " comes next: do " + point_name(c[n - 2]) + ", " + point_name(c[n - 1]) + ", " +
                point_name(i) + " turn left (counter-clockwise)?",
            structure, c, {i}, {{c[n - 1], i}});
      }
    } else if (step == Event::pop && algo_ == HullAlgo::merge) {  // the monotone chain reports no consider
      c.pop_back();
      add("pop", change,
          prefix + point_name(i) + " is popped: the chain makes no left turn at " + point_name(i) +
              ", so it leaves the chain here (the lower and the upper chain are built apart: a point one drops may be "
              "a vertex of the other).",
          structure, c, {i});
    } else if (step == Event::pop) {
      const std::size_t below = n >= 2 ? c[n - 2] : none;
      const std::size_t next = current_ != none ? current_ : c.front();  // closing: back to the pivot
      std::string why = below == none ? ""
                                      : point_name(below) + ", " + point_name(i) + ", " + point_name(next) +
                                            " make no left turn, so ";
      c.pop_back();
      add("pop", Depth::lecture,
          prefix + point_name(i) + " is popped: " + why + point_name(i) + " is no hull vertex" +
              (current_ == none ? " (closing the chain back to the pivot " + point_name(next) + ")." : "."),
          structure, c, {i, next}, below == none ? std::vector<Edge>{} : std::vector<Edge>{{below, i}, {i, next}});
    } else if (step == Event::push) {
      current_ = none;
      add("push", change, prefix + point_name(i) + " is pushed: the " + structure + " turns left all along.", structure,
          c, {i});
    }
  }

  // Jarvis: the march tells each vertex, and each point i considered with the candidate before
  // it (none for the first), the candidate after it, and the sign of Δ(u, before, i).
  void jarvis(const Report& r, const std::vector<std::size_t>& c) {
    const std::size_t i = r.at[0];
    if (r.event == Event::vertex) {
      u_ = i;
      add("vertex", Depth::lecture,
          c.size() == 1
              ? point_name(i) + ", the first point in the chart's order (leftmost, then lowest), is a hull vertex."
              : point_name(i) + " is the next hull vertex: no point lies right of " + point_name(c[c.size() - 2]) +
                    " → " + point_name(i) + ", and none lies beyond it on that line.",
          "hull so far", c, {i}, c.size() > 1 ? std::vector<Edge>{{c[c.size() - 2], i}} : std::vector<Edge>{});
      return;
    }
    if (r.event != Event::consider) return;
    const std::size_t q = r.at[1], next = r.at[2];
    std::string text;
    if (q == Report::none) {
      text = point_name(i) + " is the first candidate for the vertex after " + point_name(u_) + ".";
    } else if (next == i) {
      text = r.sign < 0 ? point_name(i) + " lies right of " + point_name(u_) + " → " + point_name(q) +
                              ": it replaces " + point_name(q) + " as the candidate."
                        : point_name(i) + " lies on the line " + point_name(u_) + " " + point_name(q) + ", beyond " +
                              point_name(q) + ": it becomes the candidate.";
    } else {
      text = point_name(i) +
             (r.sign == 0 ? " lies on the line " + point_name(u_) + " " + point_name(q) + ", not beyond " + point_name(q)
                          : " lies left of " + point_name(u_) + " → " + point_name(q)) +
             ": the candidate stays " + point_name(q) + ".";
    }
    add("consider", Depth::debugging, text, "hull so far", c, {i, next}, {{u_, next}});
  }

  // The merge: the hull of half k (1 positive, 2 negative) is done. When it holds every point
  // its chain was shown at the lecture level and the answer follows: nothing to add.
  void half(std::size_t k, const std::vector<std::size_t>& h) {
    half_ = 2;
    if (only_ != 0) return;
    std::string list;
    for (std::size_t i : h) list += (list.empty() ? "" : ", ") + point_name(i);
    if (list.empty()) list = "no point";
    if (k == 1) {
      positive_ = h;
      add("half", Depth::lecture,
          "The hull of the positive half (w > 0, then the positive part of Ω) is done: " + list + ".",
          "hull of the positive half", h, {}, {}, true);
      return;
    }
    std::vector<Edge> dashed;  // the positive half's hull beside it
    for (std::size_t j = 0; positive_.size() > 1 && j < positive_.size(); ++j)
      dashed.push_back({positive_[j], positive_[(j + 1) % positive_.size()]});
    add("half", Depth::lecture,
        "The hull of the negative half (w < 0, then the negative part of Ω) is done: " + list +
            ". It is the monotone chain of the antipodes, antipodal again and read backwards. Its vertices "
            "now join the positive half's hull (red, dashed) one at a time.",
        "hull of the negative half", h, {}, dashed, true);
  }

  void bridge(std::size_t q, std::vector<std::size_t> kept) {
    const std::size_t a = kept.back(), b = kept.front();
    kept.push_back(q);
    add("bridge", Depth::lecture,
        point_name(q) + ", a vertex of the negative half's hull, joins: it sees the hull edges from " + point_name(a) +
            " round to " + point_name(b) + " (their inner vertices leave), and the bridges " + point_name(a) + " → " +
            point_name(q) + " and " + point_name(q) + " → " + point_name(b) + " close the hull.",
        "hull so far", kept, {q}, {{a, q}, {q, b}}, true);
  }

  HullAlgo algo_;
  Recording& out_;
  std::size_t current_ = none;  // Graham: the point being considered (none after its push)
  std::size_t u_ = none;        // Jarvis: the last vertex
  std::size_t only_ = 0;               // merge: the half (1, 2) holding every point; 0: both
  std::size_t half_ = 1;               // merge: the half whose chain is running
  std::vector<std::size_t> positive_;  // merge: the positive half's hull
};

}  // namespace t2::trace
