// The hull algorithms of chapter 06 (t2/hull/convex_hull.hpp), one registration each.
#include <fmt/format.h>

#include <numeric>
#include <span>

#include "algorithms/answer.hpp"
#include "algorithms/registry.hpp"
#include "t2/hull.hpp"
#include "t2/kernel/error.hpp"
#include "t2/trace/hull_recorder.hpp"
#include "t2/trace/recording.hpp"

namespace t2cli::algorithms {
namespace {

namespace tr = t2::trace;
using t2::HullAlgorithm;

T2_PROBLEM({"hull", "vertices", Input::plane});

// The hull by `a`, as a scene.
std::function<t2::Scene(const Points&)> run(HullAlgorithm a) {
  return [a](const Points& P) { return polygons_scene(P, {t2::convex_hull(P, a)}); };
}

// A timed run of `a` on the worker's points.
std::function<Timed(BenchInput&)> timed(HullAlgorithm a) {
  return [a](BenchInput& in) -> Timed { return [&P = in.points, a] { return t2::convex_hull(P, a).size(); }; };
}

// A hull algorithm of one chart, traced: `traced(idx, chart)` runs it on every point in the chart
// of the points (none when they have no hull, or one point), then the answer step.
template <class Traced>
void record_in_chart(const Points& P, const std::string& name, tr::Recording& rec, Traced traced) {
  std::vector<std::size_t> h;
  try {
    const t2::Chart chart = t2::chart_for(std::span<const t2::Point>(P), h);  // throws when no hull
    if (h.size() != 1) {
      std::vector<std::size_t> idx(P.size());
      std::iota(idx.begin(), idx.end(), std::size_t{0});
      h = traced(idx, chart);
    }
  } catch (const t2::NoHull& e) {
    throw t2::Undefined(fmt::format("{}: no convex hull: {}", name, e.what()));
  }
  record_hull_answer(h, rec);
}

// Jarvis or Graham with the recorder.
void record_chart(HullAlgorithm a, const Points& P, const std::string& name, tr::Recording& rec) {
  record_in_chart(P, name, rec, [&](const std::vector<std::size_t>& idx, const t2::Chart& chart) {
    tr::HullRecorder r(a == HullAlgorithm::jarvis ? tr::HullAlgo::jarvis : tr::HullAlgo::graham, P, rec);
    return a == HullAlgorithm::jarvis ? t2::jarvis(std::span<const t2::Point>(P), idx, chart, r)
                                      : t2::graham(std::span<const t2::Point>(P), idx, chart, r);
  });
}

void record_merge(const Points& P, const std::string& name, tr::Recording& rec) {
  std::vector<std::size_t> h;
  try {
    tr::HullRecorder r(tr::HullAlgo::merge, P, rec);
    h = t2::merge_hull(std::span<const t2::Point>(P), r);
  } catch (const t2::NoHull& e) {
    throw t2::Undefined(fmt::format("{}: no convex hull: {}", name, e.what()));
  }
  record_hull_answer(h, rec);
}

// Chan's algorithm narrated (chan.hpp's trace): each round's group hulls, drawn over every later
// step of the round; each vertex of the wrap (lecture) after the tangents to the group hulls
// that chose it (debugging); a round that fails; Graham's own steps when one group holds all.
class ChanRecorder {
 public:
  ChanRecorder(const Points& P, tr::Recording& rec) : P_(P), rec_(rec), graham_(tr::HullAlgo::graham, P, rec) {}

  void operator()(const tr::Report& r) {
    const std::vector<std::size_t> chain(r.chain.begin(), r.chain.end());
    if (r.event == tr::Event::group_hull) {
      if (groups_.empty() || wrapping_) new_round(r.through.size());
      groups_.push_back(chain);
      tr::Step s = make_step("group",
                             fmt::format("Round {} (groups of m = {}): group {} of {} points, its hull by Graham's scan: {}.",
                                         round_, m_, groups_.size(), r.through.size(), point_list(chain)),
                             "group hull");
      s.depth = groups_.size() == 1 ? tr::Depth::lecture : tr::Depth::debugging;
      s.chain = chain;
      s.closed = true;
      s.points.assign(r.through.begin(), r.through.end());
      add(std::move(s));
    } else if (r.event == tr::Event::vertex && !groups_.empty()) {
      wrapping_ = true;
      tr::Step s = make_step("vertex",
                             fmt::format("p{} is hull vertex {} of round {}'s wrap: from it, Jarvis takes the best of "
                                         "the {} group hulls' tangents.",
                                         r.at[0], chain.size(), round_, groups_.size()),
                             "hull so far");
      s.chain = chain;
      s.points = {r.at[0]};
      add(std::move(s));
    } else if (r.event == tr::Event::tangent) {
      tr::Step s = make_step("tangent", fmt::format("The tangent from p{} to a group's hull touches p{}.", r.at[0], r.at[1]),
                             "hull so far");
      s.depth = tr::Depth::debugging;
      s.chain = chain;
      s.points = {r.at[1], r.at[0]};
      s.edges = {{r.at[0], r.at[1]}};
      add(std::move(s));
    } else {
      if (wrapping_) new_round(P_.size());  // m² ≥ n: one group, Graham's scan of every point
      wrapping_ = false;
      groups_.clear();
      graham_(r);
    }
  }

 private:
  // A round begins with groups of m points (m ≥ n: one group); after a wrap that did not close.
  void new_round(std::size_t m) {
    if (wrapping_)
      rec_.add(make_step("square",
                         fmt::format("The wrap did not close within m = {} vertices: the hull has more, so m is "
                                     "squared{}.",
                                     m_, m >= P_.size() ? ": one group holds every point, and Graham's scan ends it"
                                                        : " and the groups are made again"),
                         "hull so far"));
    groups_.clear();
    wrapping_ = false;
    ++round_;
    m_ = m;
  }
  void add(tr::Step s) {
    s.overlay = polygons_scene(P_, groups_);
    rec_.add(std::move(s));
  }

  const Points& P_;
  tr::Recording& rec_;
  tr::HullRecorder graham_;
  std::vector<std::vector<std::size_t>> groups_;  // this round's group hulls so far
  std::size_t round_ = 0, m_ = 0;
  bool wrapping_ = false;  // the round's wrap has begun
};

void record_chan(const Points& P, const std::string& name, tr::Recording& rec) {
  record_in_chart(P, name, rec, [&](const std::vector<std::size_t>& idx, const t2::Chart& chart) {
    ChanRecorder r(P, rec);
    return t2::chan(std::span<const t2::Point>(P), idx, chart, r);
  });
}

std::string named(HullAlgorithm a) { return std::string(t2::name(a)); }

T2_ALGORITHM({.name = "hull",  // what `t2 hull` runs (HullAlgorithm::automatic)
              .problem = "hull",
              .summary = "t2::convex_hull (Akl-Toussaint + monotone chain on front input, else the merge)",
              .title = "the convex hull",
              .run = run(HullAlgorithm::automatic),
              .time = timed(HullAlgorithm::automatic),
              .peers = {"cgal", "qhull"}});

T2_ALGORITHM({.name = named(HullAlgorithm::graham),
              .problem = "hull",
              .summary = "Graham's scan, O(n log n) (hulls of points of T2)",
              .title = "Graham's scan",
              .run = run(HullAlgorithm::graham),
              .record = [](const Points& P, const std::string& name,
                           tr::Recording& rec) { record_chart(HullAlgorithm::graham, P, name, rec); },
              .time = timed(HullAlgorithm::graham),
              .peers = {"jarvis"}});

T2_ALGORITHM({.name = named(HullAlgorithm::jarvis),
              .problem = "hull",
              .summary = "Jarvis's march, O(nh) (hulls of points of T2)",
              .title = "Jarvis's march",
              .run = run(HullAlgorithm::jarvis),
              .record = [](const Points& P, const std::string& name,
                           tr::Recording& rec) { record_chart(HullAlgorithm::jarvis, P, name, rec); },
              .time = timed(HullAlgorithm::jarvis)});

T2_ALGORITHM({.name = named(HullAlgorithm::merge),
              .problem = "hull",
              .summary = "the hemisphere merge of seed 000 (Algorithms 3 and 4; hulls of points of T2)",
              .title = "the hemisphere-merge hull",
              .run = run(HullAlgorithm::merge),
              .record = record_merge,
              .time = timed(HullAlgorithm::merge)});

T2_ALGORITHM({.name = named(HullAlgorithm::monotone),
              .problem = "hull",
              .summary = "Andrew's monotone chain, O(n log n)",
              .title = "the monotone chain",
              .run = run(HullAlgorithm::monotone),
              .time = timed(HullAlgorithm::monotone)});

T2_ALGORITHM({.name = named(HullAlgorithm::chan),
              .problem = "hull",
              .summary = "Chan's algorithm, O(n log h): Graham on groups, Jarvis with tangents",
              .title = "Chan's algorithm",
              .run = run(HullAlgorithm::chan),
              .record = record_chan,
              .time = timed(HullAlgorithm::chan),
              .peers = {"graham", "cgal"}});

T2_ALGORITHM({.name = named(HullAlgorithm::quickhull),
              .problem = "hull",
              .summary = "Quickhull, O(n log n) on average",
              .title = "Quickhull",
              .run = run(HullAlgorithm::quickhull),
              .time = timed(HullAlgorithm::quickhull)});

}  // namespace
}  // namespace t2cli::algorithms
