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

// Jarvis or Graham with the recorder, in the chart of the points (none when they have no hull).
void record_chart(HullAlgorithm a, const Points& P, const std::string& name, tr::Recording& rec) {
  std::vector<std::size_t> h;
  try {
    const t2::Chart chart = t2::chart_for(std::span<const t2::Point>(P), h);  // throws when no hull
    if (h.size() != 1) {
      std::vector<std::size_t> idx(P.size());
      std::iota(idx.begin(), idx.end(), std::size_t{0});
      tr::HullRecorder r(a == HullAlgorithm::jarvis ? tr::HullAlgo::jarvis : tr::HullAlgo::graham, P, rec);
      h = a == HullAlgorithm::jarvis ? t2::jarvis(std::span<const t2::Point>(P), idx, chart, r)
                                     : t2::graham(std::span<const t2::Point>(P), idx, chart, r);
    }
  } catch (const t2::NoHull& e) {
    throw t2::Undefined(fmt::format("{}: no convex hull: {}", name, e.what()));
  }
  record_hull_answer(h, rec);
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
