#pragma once
/// @file fortune_recorder.hpp
/// @brief The recorder of Fortune's sweep (voronoi/fortune.hpp) for `t2 animate fortune`: it
/// hears the sweep's reports (trace/hook.hpp: site, circle, schedule, false_alarm, breakpoint)
/// and turns each into a step; it never runs the sweep itself.
///
/// - **Lecture steps** (the beach line changes): a site event (the new site, the arc it splits)
///   and a circle event (the circle through three sites, its centre as a new Voronoi vertex,
///   the middle arc gone).
/// - **Debugging steps**: the search for the arc above a site (one step: each breakpoint
///   comparison it made, in order), each false alarm (a queued circle event dropped). Each
///   circle event queued is said in the text of the step it follows (a step of its own each
///   made a page of 200 points weigh several megabytes).
///
/// Every step shows the sweep line (its visible part, an overlay segment across the picture),
/// the beach line as its structure (the sites of its arcs left to right, an open chain of input
/// indices) and, for at most `kCurveSites` sites, as parabolic arcs (each arc a polyline of the
/// page: beyond that the page outgrows 1 MB), and the Voronoi edges finished so far (segments
/// between two vertices). A circle is an overlay
/// circle by its exact centre (the circumcentre, `to_double`: exact while its homogeneous
/// coordinates fit in doubles, as for small integer sites) and one of its sites.
///
/// **What is not exact.** The sweep line of a circle event is y = c_y + √R, and the arcs and
/// breakpoints of the beach line need square roots: they are computed in doubles and sampled
/// (`Step::curves`), a picture of the curve and nothing more. No decision reads them: every
/// decision is the sweep's own, exact.

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "t2/kernel/circle.hpp"
#include "t2/kernel/point.hpp"
#include "t2/trace/hook.hpp"
#include "t2/trace/overlay.hpp"
#include "t2/trace/recording.hpp"
#include "t2/voronoi/voronoi.hpp"

namespace t2::trace {

/// Hears Fortune's sweep on the sites P and adds its steps to a recording (file comment).
class FortuneRecorder {
 public:
  /// The most sites whose beach line is drawn as arcs (the file comment).
  static constexpr std::size_t kCurveSites = 30;

  /// @param P the sites, as given to `t2::fortune` (front side)
  /// @param rec the recording the steps go to
  FortuneRecorder(const std::vector<Point>& P, Recording& rec) : P_(P), rec_(rec) {
    double r = 0;
    for (const Point& p : P) r = std::max(r, std::hypot(p.x() / p.w(), p.y() / p.w()));
    h_ = std::max(1.0, 1.15 * r);  // the half width of the planar picture (animate/frame.cpp)
  }

  /// Hears one report of the sweep.
  void operator()(const Report& r) {
    const std::vector<std::size_t> beach(r.chain.begin(), r.chain.end());
    switch (r.event) {
      case Event::site: return site(r, beach);
      case Event::circle: return circle(r, beach);
      case Event::schedule:
        if (pending_) pending_->text += fmt::format(" The circle of {}, {}, {} joins the event queue.",
                                                    name(r.at[0]), name(r.at[1]), name(r.at[2]));
        return;
      case Event::false_alarm: return alarm(r, beach);
      case Event::breakpoint: return breakpoint(r, beach);
      default: return;
    }
  }

  /// Adds the last step heard (call it once the sweep is over, before the answer).
  void finish() {
    if (pending_) rec_.add(std::move(*pending_));
    pending_.reset();
  }

  /// The Voronoi vertices the circle events made, in order (exact circumcentres).
  const std::vector<ExactPoint>& vertices() const { return vertices_; }
  /// The Voronoi edges finished so far, as pairs of vertices (drawn as segments).
  const std::vector<std::pair<ExactPoint, ExactPoint>>& edges() const { return finished_; }

 private:
  static std::string name(std::size_t i) { return point_name(i); }

  /// A step with the sweep line (y = y_, across the picture), the beach line, the finished edges.
  Step step(const char* kind, Depth d, std::string text, const std::vector<std::size_t>& beach) const {
    Step s;
    s.kind = kind;
    s.depth = d;
    s.text = std::move(text);
    s.structure = "beach line";
    s.chain = beach;
    add_segment(s.overlay, Point(1, -h_, y_), Point(1, h_, y_));  // the sweep line's visible part
    for (const auto& [a, b] : finished_) add_segment(s.overlay, to_double(a), to_double(b));
    if (P_.size() <= kCurveSites) s.curves = arcs(beach);
    return s;
  }

  /// Holds s until the next report (a circle event queued adds its sentence to it).
  void add(Step s) {
    finish();
    pending_ = std::move(s);
  }

  void site(const Report& r, const std::vector<std::size_t>& beach) {
    const std::size_t p = r.at[0];
    set_sweep(P_[p]);
    if (!search_.empty()) {  // the search for the arc above p, before the split
      Step s = step("locate", Depth::debugging,
                    fmt::format("Which arc lies above {}? The search down the beach line's tree: {} is {}.", name(p),
                                name(p), search_),
                    search_beach_);
      s.points = search_points_;
      add(std::move(s));
      search_.clear();
      search_points_.clear();
    }
    std::string text =
        r.at[1] == Report::none
            ? (beach.size() == 1 ? fmt::format("Site event: the sweep line reaches {}, the lowest site: the beach "
                                               "line is its arc.",
                                               name(p))
                                 : fmt::format("Site event: {} lies on the first row, as low as the first site: its "
                                               "arc joins the beach line on the right, a vertical bisector between.",
                                               name(p)))
            : fmt::format("Site event: the sweep line reaches {}; its arc splits the arc of {} in two.", name(p),
                          name(r.at[1]));
    Step s = step("site", Depth::lecture, std::move(text), beach);
    s.points = {p};
    if (r.at[1] != Report::none) s.points.push_back(r.at[1]);
    add(std::move(s));
  }

  void circle(const Report& r, const std::vector<std::size_t>& beach) {
    const std::size_t a = r.at[0], b = r.at[1], c = r.at[2];
    const ExactPoint v = circumcentre(P_[a], P_[b], P_[c]);
    const double cx = mpq_class(v.x(), v.w()).get_d(), cy = mpq_class(v.y(), v.w()).get_d();
    const double dx = P_[a].x() / P_[a].w() - cx, dy = P_[a].y() / P_[a].w() - cy;
    set_sweep(Point(1, cx, cy + std::sqrt(dx * dx + dy * dy)));  // y = c_y + √R: drawing only
    // The two bisectors that reach v end there; a third (a, c) starts.
    for (auto [s, t] : {std::pair{a, b}, std::pair{b, c}}) {
      const auto key = std::minmax(s, t);
      if (const auto it = open_.find(key); it != open_.end()) {
        if (!(it->second == v)) finished_.push_back({it->second, v});
        open_.erase(it);
      } else {
        open_.emplace(key, v);
      }
    }
    open_.emplace(std::minmax(a, c), v);
    vertices_.push_back(v);
    Step s = step("circle", Depth::lecture,
                  fmt::format("Circle event: the sweep line touches the top of the circle through {}, {}, {}. The arc "
                              "of {} shrinks to a point and leaves the beach line; the circle's centre is Voronoi "
                              "vertex v{}.",
                              name(a), name(b), name(c), name(b), vertices_.size() - 1),
                  beach);
    add_circle(s.overlay, Circle(to_double(v), P_[a]));
    add_point(s.overlay, to_double(v));
    s.points = {b, a, c};
    add(std::move(s));
  }

  void alarm(const Report& r, const std::vector<std::size_t>& beach) {
    const std::size_t a = r.at[0], b = r.at[1], c = r.at[2];
    Step s = step("false alarm", Depth::debugging,
                  fmt::format("False alarm: the arcs of {}, {}, {} are no longer neighbours; their circle event "
                              "leaves the queue.",
                              name(a), name(b), name(c)),
                  beach);
    add_circle(s.overlay, Circle(to_double(circumcentre(P_[a], P_[b], P_[c])), P_[a]));
    s.points = {b, a, c};
    add(std::move(s));
  }

  /// One comparison of the search for the arc above at[2], kept for its step (`site`).
  void breakpoint(const Report& r, const std::vector<std::size_t>& beach) {
    const char* where = r.sign == POSITIVE ? "left of" : r.sign == ZERO ? "on" : "right of";
    search_ += fmt::format("{}{} the breakpoint of {} and {}", search_.empty() ? "" : "; ", where, name(r.at[0]),
                           name(r.at[1]));
    for (std::size_t i : {r.at[2], r.at[0], r.at[1]})
      if (std::find(search_points_.begin(), search_points_.end(), i) == search_points_.end()) search_points_.push_back(i);
    search_beach_ = beach;
  }

  /// The sweep line through `at` (a site, or the top of a circle: doubles, drawing only).
  void set_sweep(const Point& at) {
    y_ = at.y() / at.w();
  }

  /// The beach line at the sweep's height y_, sampled left to right (drawing only: doubles).
  std::vector<std::vector<Point>> arcs(const std::vector<std::size_t>& beach) const {
    std::vector<std::vector<Point>> out(1);
    const double L = y_;
    auto X = [&](std::size_t i) { return P_[i].x() / P_[i].w(); };
    auto Y = [&](std::size_t i) { return P_[i].y() / P_[i].w(); };
    auto height = [&](std::size_t i, double x) {  // the parabola of site i at x
      const double d = Y(i) - L;
      return ((x - X(i)) * (x - X(i)) + Y(i) * Y(i) - L * L) / (2 * d);
    };
    auto cut = [&](std::size_t p, std::size_t q) {  // the breakpoint of the arcs of p (left), q (right)
      const double dp = Y(p) - L, dq = Y(q) - L;
      if (dp == dq) return (X(p) + X(q)) / 2;
      const double dx = X(p) - X(q), dy = Y(p) - Y(q);
      return (dq * X(p) - dp * X(q) - std::sqrt(std::max(0.0, dp * dq * (dx * dx + dy * dy)))) / (dq - dp);
    };
    auto put = [&](double x, double y) {
      if (std::isfinite(y) && std::fabs(y) <= 4 * h_) out.back().push_back(Point(1, x, y));
      else if (!out.back().empty()) out.emplace_back();
    };
    for (std::size_t k = 0; k < beach.size(); ++k) {
      const std::size_t i = beach[k];
      if (!(Y(i) < L)) {  // an arc of zero width: the vertical from its site down to the beach line
        const double end = k > 0 && Y(beach[k - 1]) < L ? height(beach[k - 1], X(i))
                           : k + 1 < beach.size() && Y(beach[k + 1]) < L ? height(beach[k + 1], X(i))
                                                                          : L - 2 * h_;
        out.push_back({Point(1, X(i), Y(i)), Point(1, X(i), std::max(end, L - 2 * h_))});
        out.emplace_back();
        continue;
      }
      const double lo = std::max(-h_, k > 0 ? cut(beach[k - 1], i) : -h_);
      const double hi = std::min(h_, k + 1 < beach.size() ? cut(i, beach[k + 1]) : h_);
      if (!(lo < hi)) continue;
      const int n = 1 + static_cast<int>(std::ceil((hi - lo) / (2 * h_) * 16));
      for (int j = 0; j <= n; ++j) put(lo + (hi - lo) * j / n, height(i, lo + (hi - lo) * j / n));
    }
    std::erase_if(out, [](const std::vector<Point>& c) { return c.size() < 2; });
    return out;
  }

  const std::vector<Point>& P_;
  Recording& rec_;
  double h_ = 1;                    // half width of the picture
  double y_ = 0;                    // the sweep's height (drawing only)
  std::vector<ExactPoint> vertices_;
  std::map<std::pair<std::size_t, std::size_t>, ExactPoint> open_;  // a bisector with one vertex
  std::vector<std::pair<ExactPoint, ExactPoint>> finished_;
  std::optional<Step> pending_;             // the last step, until the next report
  std::string search_;                      // the comparisons of the search for the next site's arc
  std::vector<std::size_t> search_points_;  // the sites they name, the new site first
  std::vector<std::size_t> search_beach_;   // the beach line they searched
};

}  // namespace t2::trace
