// The triangulations of chapters 09 and 10 (t2/triangulation/*), one registration each.
#include <fmt/format.h>

#include <algorithm>
#include <span>

#include "algorithms/answer.hpp"
#include "algorithms/registry.hpp"
#include "t2/kernel/error.hpp"
#include "t2/trace/delaunay_recorder.hpp"
#include "t2/trace/recording.hpp"
#include "t2/trace/sweep_recorder.hpp"
#include "t2/trace/triangulate_t2_recorder.hpp"
#include "t2/triangulation/delaunay.hpp"
#include "t2/triangulation/divide.hpp"
#include "t2/triangulation/insert_t2.hpp"
#include "t2/triangulation/triangulate.hpp"

namespace t2cli::algorithms {
namespace {

namespace tr = t2::trace;

T2_PROBLEM({"delaunay", "triangles", Input::plane});
T2_PROBLEM({"triangulation", "triangles", Input::plane});

// `f` names the scene when it finds the answer undefined.
template <class F>
auto naming(const std::string& name, F f) {
  try {
    return f();
  } catch (const t2::Undefined& e) {
    throw t2::Undefined(fmt::format("{}: {}", name, e.what()));
  }
}

void record_delaunay(const Points& P, const std::string& name, tr::Recording& rec) {
  require_front(P, name, "delaunay");
  tr::DelaunayRecorder k(P, rec);
  const auto t = naming(name, [&] { return t2::delaunay_with(std::span<const t2::Point>(P), t2::DelaunayTraits{}, k); });
  record_triangles_answer(t, "Delaunay triangulation", rec);
}

// Algorithm 9 on T² in spatial order (triangulate_t2.hpp), with its recorder.
void record_triangulate_t2(const Points& P, const std::string& name, tr::Recording& rec, const std::string& what) {
  tr::TriangulateT2Recorder r(rec);
  const auto t = naming(name, [&] {
    return t2::triangulate_t2(std::span<const t2::Point>(P), t2::InsertionOrder::spatial, r);
  });
  record_triangles_answer(t.tr, what, rec);
}

// What `t2 triangulate` runs, told to the recorder of the algorithm it takes: the sweep on front
// points, Algorithm 9 on T² otherwise (`t2::triangulate` forwards its hook there).
void record_triangulate(const Points& P, const std::string& name, tr::Recording& rec) {
  const std::span<const t2::Point> input(P);
  if (std::all_of(P.begin(), P.end(), [](const t2::Point& p) { return p.w() > 0; })) {
    tr::SweepRecorder r(rec);
    const auto t = naming(name, [&] { return t2::triangulate(input, r); });
    return record_triangles_answer(t, "sweep triangulation (t2 triangulate)", rec);
  }
  tr::TriangulateT2Recorder r(rec);
  const auto t = naming(name, [&] { return t2::triangulate(input, r); });
  record_triangles_answer(t, "triangulation of T2 (Algorithm 9, t2 triangulate)", rec);
}

T2_ALGORITHM({.name = "delaunay",  // what `t2 delaunay` runs
              .problem = "delaunay",
              .summary = "t2::delaunay, the randomized incremental insertion with Lawson flips (animated on "
                         "front points)",
              .title = "randomized incremental Delaunay",
              .run = [](const Points& P) { return triangles_scene(P, t2::delaunay(P)); },
              .record = record_delaunay,
              .time = [](BenchInput& in) -> Timed { return [&P = in.points] { return finite_count(t2::delaunay(P)); }; },
              .peers = {"divide", "cgal"}});

T2_ALGORITHM({.name = "owned",
              .problem = "delaunay",
              .summary = "t2::delaunay(std::move(points)): the result takes the input vector (one copy of the points)",
              .title = "randomized incremental Delaunay (owned points)",
              .run = [](const Points& P) { return triangles_scene(P, t2::delaunay(Points(P))); },
              .time = [](BenchInput& in) -> Timed {
                return [&P = in.points] { return finite_count(t2::delaunay(std::move(P))); };
              }});

T2_ALGORITHM({.name = "divide",
              .problem = "delaunay",
              .summary = "t2::delaunay_divide (Guibas-Stolfi divide and conquer, quad-edge)",
              .title = "divide-and-conquer Delaunay",
              .run = [](const Points& P) { return triangles_scene(P, t2::delaunay_divide(P)); },
              .time = [](BenchInput& in) -> Timed {
                return [&P = in.points] { return finite_count(t2::delaunay_divide(P)); };
              }});

T2_ALGORITHM({.name = "triangulate",  // what `t2 triangulate` runs
              .problem = "triangulation",
              .summary = "t2::triangulate: the sweep of chapter 09 on front points (one step per point, its "
                         "new fan; the flips of step 35 at the debugging level), Algorithm 9 on T2 otherwise",
              .title = "t2::triangulate (the sweep; Algorithm 9 on T2)",
              .run = [](const Points& P) { return triangles_scene(P, t2::triangulate(P)); },
              .record = record_triangulate,
              .time = [](BenchInput& in) -> Timed {
                return [&P = in.points] { return finite_count(t2::triangulate(P)); };
              },
              .peers = {"triangulate-t2"}});

T2_ALGORITHM({.name = "triangulate-t2",
              .problem = "triangulation",
              .summary = "t2::triangulate_t2: Algorithm 9 on T2, insertion in spatial order, flips only where "
                         "the new point sees hull edges",
              .title = "Algorithm 9 on T2 (t2::triangulate_t2)",
              .run = [](const Points& P) { return triangles_scene(P, t2::triangulate_t2(P).tr); },
              .record = [](const Points& P, const std::string& name,
                           tr::Recording& rec) { record_triangulate_t2(P, name, rec, "triangulation by Algorithm 9"); },
              .time = [](BenchInput& in) -> Timed {
                return [&P = in.points] { return finite_count(t2::triangulate_t2(P).tr); };
              }});

}  // namespace
}  // namespace t2cli::algorithms
