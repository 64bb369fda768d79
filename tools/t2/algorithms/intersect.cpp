// The segment intersections of chapter 13 (t2/intersect/intersections.hpp), one registration
// each: timed by `t2 bench` on `t2 gen segments` (n segments with exactly n crossings); the two
// sweeps are animated too (`t2 animate intersect`, `t2 animate intersect-circular`): the sweep
// line at each event, the status as its segments, each point found, each neighbour test.
#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <functional>
#include <optional>

#include "algorithms/answer.hpp"
#include "algorithms/registry.hpp"
#include "t2/intersect/intersections.hpp"
#include "t2/kernel/error.hpp"
#include "t2/trace/hook.hpp"
#include "t2/trace/overlay.hpp"
#include "t2/trace/recording.hpp"

namespace t2cli::algorithms {
namespace {

T2_PROBLEM({"intersect", "points", Input::segments});

// The number of intersection points `a` reports on the segments of `in`.
Timed timed(BenchInput& in, t2::IntersectAlgorithm a) {
  return [&S = in.segments, a] { return t2::intersections(S, a).size(); };
}

namespace tr = t2::trace;
using Segments = std::vector<t2::Segment>;

// "s3, s1 and s4"
std::string segment_list(const std::vector<std::size_t>& v) {
  std::vector<std::string> names;
  for (std::size_t i : v) names.push_back(fmt::format("s{}", i));
  return words(names, "and");
}

// A point for a step's text: exact when its integers are short, else its Cartesian
// coordinates rounded (the overlay holds the point itself).
std::string where(const t2::ExactPoint& p) {
  const auto bits = [](const t2::Integer& v) { return mpz_sizeinbase(v.get_mpz_t(), 2); };
  if (std::max({bits(p.w()), bits(p.x()), bits(p.y())}) <= 20) return t2::to_string(p);
  const t2::Point d = t2::to_double(p);
  if (d.w() == 0) return t2::to_string(t2::normalized(d));
  return fmt::format("{}({:.4g}, {:.4g})", d.w() < 0 ? "the antipode of " : "about ", d.x() / d.w(), d.y() / d.w());
}

// The narrator of a sweep's reports (trace/hook.hpp's sweep events): a step per change of the
// status (lecture), per point found (lecture) and per neighbour test (debugging). It keeps only
// what the reports lent it: the status after the last event, the event, the points found.
class SweepNarrator {
 public:
  explicit SweepNarrator(tr::Recording& rec) : rec_(rec) {}

  void operator()(const tr::Report& r) {
    switch (r.event) {
      case tr::Event::sweep_start: start(r); break;
      case tr::Event::found: found(r); break;
      case tr::Event::sweep: sweep(r); break;
      case tr::Event::neighbours: neighbours(r); break;
      default: break;
    }
  }

  // The last step: the answer of the run, every point found.
  void answer(const std::vector<t2::IntersectionPoint>& points) {
    std::vector<std::string> lines;
    t2::Scene overlay;
    for (const auto& p : points) {
      lines.push_back(fmt::format("{} on {}", where(p.point), segment_list(p.segments)));
      tr::add_point(overlay, t2::to_double(p.point));
    }
    tr::Step s = make_step("answer",
                           points.empty() ? std::string("No intersection point.")
                                          : fmt::format("{} intersection point{}: {}.", points.size(),
                                                        points.size() == 1 ? "" : "s", fmt::join(lines, "; ")),
                           "status");
    s.overlay = std::move(overlay);
    rec_.add(std::move(s));
  }

 private:
  // A step with the status, the sweep line at the current event and the points found so far.
  tr::Step step(const char* kind, std::string text, tr::Depth depth, const std::vector<std::size_t>& status) const {
    tr::Step s = make_step(kind, std::move(text), "status");
    s.depth = depth;
    s.chain = status;
    if (centre_) {
      tr::add_point(s.overlay, *centre_, "o");
      if (event_) {  // the half-line from o through the event to ¬o
        tr::add_segment(s.overlay, *centre_, *event_);
        tr::add_segment(s.overlay, *event_, t2::antipode(*centre_));
      }
    } else if (event_) {  // the vertical line through the event
      tr::add_line(s.overlay, *event_, t2::Point(0, 0, 1));
    }
    for (const auto& p : found_) tr::add_point(s.overlay, p);
    return s;
  }

  static void focus(tr::Step& s, const std::vector<std::size_t>& segments) {
    for (std::size_t i : segments) s.edges.push_back({2 * i, 2 * i + 1});
  }

  void start(const tr::Report& r) {
    centre_ = t2::to_double(*r.point);
    event_ = t2::Point(0, 1, 0);  // the initial half-line, through [0, 1, 0]
    const std::vector<std::size_t> cut(r.chain.begin(), r.chain.end());
    tr::Step s = step("start",
                      fmt::format("The sweep half-line turns counter-clockwise around o = {}, from its position "
                                  "through [0, 1, 0]. {}",
                                  where(*r.point),
                                  cut.empty() ? std::string("It crosses no segment there.")
                                              : fmt::format("It cuts {} there, each into two pieces, one swept "
                                                            "first and one last; no point is reported between them.",
                                                            segment_list(cut))),
                      tr::Depth::lecture, {});
    focus(s, cut);
    rec_.add(std::move(s));
  }

  void found(const tr::Report& r) {
    const t2::Point p = t2::to_double(*r.point);
    const std::vector<std::size_t> through(r.chain.begin(), r.chain.end());
    found_.push_back(p);
    event_ = p;  // the circular sweep judges the points of its initial half-line after the turn
    tr::Step s = step("intersection",
                      fmt::format("{} meet at {}: an intersection point.", segment_list(through), where(*r.point)),
                      tr::Depth::lecture, status_);
    focus(s, through);
    rec_.add(std::move(s));
  }

  void sweep(const tr::Report& r) {
    event_ = t2::to_double(*r.point);
    const std::vector<std::size_t> now(r.chain.begin(), r.chain.end()), through(r.through.begin(), r.through.end());
    const auto in = [](const std::vector<std::size_t>& v, std::size_t i) {
      return std::find(v.begin(), v.end(), i) != v.end();
    };
    std::vector<std::size_t> ended, started, going;  // going: through the event and in the status before it
    for (std::size_t i : status_)
      if (!in(now, i)) ended.push_back(i);
    for (std::size_t i : through) (in(status_, i) ? going : started).push_back(i);
    std::vector<std::size_t> before_order;  // the going ones in their order before the event
    for (std::size_t i : status_)
      if (in(going, i)) before_order.push_back(i);
    const bool swapped = before_order != going;
    const std::string at = where(*r.point);
    if (!ended.empty()) {
      std::vector<std::size_t> left;
      for (std::size_t i : status_)
        if (!in(ended, i)) left.push_back(i);
      tr::Step s = step("delete",
                        fmt::format("The sweep line reaches {}, where {} end{}: out of the status.", at,
                                    segment_list(ended), ended.size() == 1 ? "s" : ""),
                        tr::Depth::lecture, left);
      focus(s, ended);
      rec_.add(std::move(s));
    }
    if (swapped) {
      tr::Step s = step("swap",
                        fmt::format("At {}, {} cross: their order in the status reverses{}.", at,
                                    segment_list(before_order),
                                    started.empty() ? "" : fmt::format(", and {} enter{} it", segment_list(started),
                                                                       started.size() == 1 ? "s" : "")),
                        tr::Depth::lecture, now);
      focus(s, going);
      rec_.add(std::move(s));
    } else if (!started.empty()) {
      tr::Step s = step("insert",
                        fmt::format("The sweep line reaches {}, where {} start{}: into the status, in order along "
                                    "the sweep line.",
                                    at, segment_list(started), started.size() == 1 ? "s" : ""),
                        tr::Depth::lecture, now);
      focus(s, started);
      rec_.add(std::move(s));
    } else if (ended.empty()) {
      tr::Step s = step("event", fmt::format("The sweep line passes {}: the status does not change.", at),
                        tr::Depth::debugging, now);
      focus(s, through);
      rec_.add(std::move(s));
    }
    status_ = now;
  }

  void neighbours(const tr::Report& r) {
    const std::vector<std::size_t> pair{r.at[0], r.at[1]};
    const std::string what =
        r.sign == t2::POSITIVE   ? "cross ahead of the sweep line: their crossing joins the queue"
        : r.sign == t2::NEGATIVE ? "do not cross ahead of the sweep line"
                                 : "lie on parallel lines or on one line: no crossing to queue (an overlap ends at endpoints)";
    tr::Step s = step("test", fmt::format("Neighbours in the status: {} {}.", segment_list(pair), what),
                      tr::Depth::debugging, status_);
    focus(s, pair);
    rec_.add(std::move(s));
  }

 private:
  tr::Recording& rec_;
  std::optional<t2::Point> centre_, event_;
  std::vector<std::size_t> status_;
  std::vector<t2::Point> found_;
};

// Bentley-Ottmann with its narrator; throws t2::Undefined naming the scene for a segment not in
// front (what `t2 intersect` does: exit 3).
void record_sweep(const Segments& S, const std::string& name, tr::Recording& rec) {
  SweepNarrator n(rec);
  std::vector<t2::IntersectionPoint> points;
  try {
    points = t2::intersections_sweep(S, std::ref(n));
  } catch (const t2::Undefined& e) {
    throw t2::Undefined(fmt::format("{}: {} (t2 animate intersect-circular takes it)", name, e.what()));
  }
  n.answer(points);
}

// The circular sweep of T² with its narrator: every segment of T².
void record_circular(const Segments& S, const std::string& name, tr::Recording& rec) {
  (void)name;  // every set of segments of T² is swept
  SweepNarrator n(rec);
  n.answer(t2::intersections_circular(S, std::ref(n)));
}

T2_ALGORITHM({.name = "intersect",  // what `t2 intersect` runs
              .problem = "intersect",
              .summary = "t2::intersections, Bentley-Ottmann's sweep (front segments), O((n + k) log n)",
              .title = "Bentley-Ottmann sweep",
              .record_segments = record_sweep,
              .time = [](BenchInput& in) { return timed(in, t2::IntersectAlgorithm::sweep); },
              .peers = {"intersect-brute", "intersect-circular", "cgal"}});

T2_ALGORITHM({.name = "intersect-brute",
              .problem = "intersect",
              .summary = "t2::intersections by brute force, every pair, O(n^2), on the whole of T2",
              .title = "every pair of segments",
              .time = [](BenchInput& in) { return timed(in, t2::IntersectAlgorithm::brute); }});

T2_ALGORITHM({.name = "intersect-circular",  // t2 intersect --algorithm circular
              .problem = "intersect",
              .summary = "t2::intersections by the circular sweep of T2 (seed 000, Algorithm 16), O((n + k) log n), "
                         "every segment of T2",
              .title = "circular sweep of T2",
              .record_segments = record_circular,
              .time = [](BenchInput& in) { return timed(in, t2::IntersectAlgorithm::circular); }});

}  // namespace
}  // namespace t2cli::algorithms
