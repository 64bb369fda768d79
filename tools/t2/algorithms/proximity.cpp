// The proximity problems of T² (chapter 12, t2/proximity/), timed by `t2 bench` on points of
// the plane; Welzl's smallest enclosing circle is animated too (Kruskal's animation is issue
// 25's later part). Each but the three `sec` ones (Shamos's builds the whole complex) and `closest-pair-divide`
// builds the Delaunay triangulation of each side in its run, so `t2 bench emst delaunay` compares the whole cost with
// the triangulation's.
#include <fmt/format.h>

#include <algorithm>

#include "algorithms/answer.hpp"
#include "algorithms/registry.hpp"
#include "t2/kernel/circle.hpp"
#include "t2/kernel/error.hpp"
#include "t2/trace/overlay.hpp"
#include "t2/trace/recording.hpp"
#include "t2/proximity/closest_pair.hpp"
#include "t2/proximity/empty_circle.hpp"
#include "t2/proximity/enclosing_circle.hpp"
#include "t2/proximity/enclosing_circle_voronoi.hpp"
#include "t2/proximity/nearest_neighbors.hpp"
#include "t2/proximity/spanning_tree.hpp"

namespace t2cli::algorithms {
namespace {

T2_PROBLEM({"emst", "edges", Input::plane});
T2_PROBLEM({"ann", "sites", Input::plane});
T2_PROBLEM({"closest-pair", "pairs", Input::plane});
T2_PROBLEM({"sec", "support sites", Input::plane});
T2_PROBLEM({"lec", "sites on the circle", Input::plane});

T2_ALGORITHM({.name = "emst",  // what `t2 emst` runs
              .problem = "emst",
              .summary = "t2::minimum_spanning_tree: Kruskal on the Delaunay edges of each side of T2 (Algorithm 12)",
              .title = "the minimum spanning tree of T2 (Kruskal on the Delaunay edges)",
              .time = [](BenchInput& in) -> Timed {
                return [&P = in.points] { return t2::minimum_spanning_tree(std::span<const t2::Point>(P)).size(); };
              }});

T2_ALGORITHM({.name = "ann",  // what `t2 ann` runs
              .problem = "ann",
              .summary = "t2::all_nearest_neighbors: each site's nearest among its Delaunay neighbours (Algorithm 14)",
              .title = "all nearest neighbours in T2 (the Delaunay neighbours)",
              .time = [](BenchInput& in) -> Timed {
                return [&P = in.points] { return t2::all_nearest_neighbors(std::span<const t2::Point>(P)).size(); };
              }});

T2_ALGORITHM({.name = "closest-pair",  // what `t2 closest-pair` runs (--algorithm delaunay)
              .problem = "closest-pair",
              .summary = "t2::closest_pair: the nearest of the Delaunay edges of each side of T2",
              .title = "the closest pair in T2 (the Delaunay edges)",
              .time = [](BenchInput& in) -> Timed {
                return [&P = in.points] {
                  t2::closest_pair(std::span<const t2::Point>(P));
                  return std::size_t(1);
                };
              }});

T2_ALGORITHM({.name = "closest-pair-divide",  // t2 closest-pair --algorithm divide
              .problem = "closest-pair",
              .summary = "t2::closest_pair_divide: Shamos-Hoey divide and conquer on each side of T2",
              .title = "the closest pair in T2 (divide and conquer)",
              .time = [](BenchInput& in) -> Timed {
                return [&P = in.points] {
                  t2::closest_pair_divide(std::span<const t2::Point>(P));
                  return std::size_t(1);
                };
              }});

namespace tr = t2::trace;

// The circle of the sites `d` of P (one: the point, two: a diameter, three: through them) and
// its centre, as an overlay (trace/overlay.hpp).
t2::Scene disk_scene(const Points& P, const std::vector<std::size_t>& d) {
  t2::Scene s;
  t2::Point c = P[d[0]];
  if (d.size() >= 2) {
    const t2::ExactPoint a = t2::to_exact(P[d[0]]), b = t2::to_exact(P[d[1]]);
    c = t2::to_double(d.size() == 2 ? t2::circle_from_diameter(a, b).center()
                                    : t2::circle_through(a, b, t2::to_exact(P[d[2]])).center());
    tr::add_circle(s, t2::Circle(c, P[d[0]]));
  }
  tr::add_point(s, c, "centre");
  return s;
}

// The answer as a scene: the smallest enclosing circle and its centre.
t2::Scene sec_scene(const Points& P) {
  if (P.empty()) return {};
  const t2::EnclosingCircle c = t2::smallest_enclosing_circle(std::span<const t2::Point>(P));
  return disk_scene(P, std::vector<std::size_t>(c.support.begin(), c.support.end()));
}

// Welzl's algorithm with a recorder: each new disk a lecture step, each test a debugging one.
void record_welzl(const Points& P, const std::string& name, tr::Recording& rec) {
  if (!std::all_of(P.begin(), P.end(), [](const t2::Point& p) { return p.w() > 0; }))
    throw t2::BadInput(fmt::format("{}: t2 animate sec takes front points only (w > 0); t2 sec answers for back "
                                   "points and exits with 3 for mixed ones",
                                   name));
  if (P.empty()) {
    rec.add(make_step("answer", "No point: no circle.", "defining sites"));
    return;
  }
  std::vector<std::size_t> disk;
  const auto hook = [&](const tr::Report& r) {
    if (r.event == tr::Event::enclose) {
      disk.assign(r.points().begin(), r.points().end());
      tr::Step s = make_step(
          "disk",
          disk.size() == 3   ? fmt::format("The circle through {}.", point_list(disk))
          : disk.size() == 2 ? fmt::format("The circle with diameter {}.", point_list(disk))
                             : fmt::format("One point, {}: the disk of radius zero.", point_list(disk)),
          "defining sites");
      s.chain = disk;  // a diameter, or the triangle of a circumcircle
      s.closed = disk.size() == 3;
      s.points = disk;
      s.overlay = disk_scene(P, disk);
      rec.add(std::move(s));
    } else if (r.event == tr::Event::in_disk) {
      const char* where = r.sign == t2::POSITIVE ? "inside" : r.sign == t2::ZERO ? "on" : "outside";
      tr::Step s = make_step("test",
                             fmt::format("p{} is {} the circle of {}{}", r.at[0], where, point_list(disk),
                                         r.sign == t2::NEGATIVE ? ": it must be on the next one." : "."),
                             "defining sites");
      s.depth = tr::Depth::debugging;
      s.chain = disk;
      s.closed = disk.size() == 3;
      s.points = {r.at[0]};
      s.overlay = disk_scene(P, disk);
      rec.add(std::move(s));
    }
  };
  const t2::EnclosingCircle c = t2::smallest_enclosing_circle(std::span<const t2::Point>(P), hook);
  std::vector<std::size_t> on(c.on_circle.begin(), c.on_circle.end());
  tr::Step s = make_step("answer",
                         fmt::format("The smallest enclosing circle: squared radius {}, with {} on it.",
                                     c.radius2.get_str(), point_list(on)),
                         "defining sites");
  s.chain = std::vector<std::size_t>(c.support.begin(), c.support.end());
  s.closed = s.chain.size() == 3;
  s.points = on;
  s.overlay = sec_scene(P);
  rec.add(std::move(s));
}

T2_ALGORITHM({.name = "sec",  // what `t2 sec` runs
              .problem = "sec",
              .summary = "t2::smallest_enclosing_circle: Welzl's randomized algorithm, expected O(n) exact predicates (animated on front points)",
              .title = "the smallest enclosing circle (Welzl)",
              .run = sec_scene,
              .record = record_welzl,
              .time = [](BenchInput& in) -> Timed {
                return [&P = in.points] {
                  return t2::smallest_enclosing_circle(std::span<const t2::Point>(P)).support.size();
                };
              },
              .peers = {"cgal", "sec-shamos", "sec-bt"}});

T2_ALGORITHM({.name = "sec-shamos",  // t2 sec --algorithm shamos
              .problem = "sec",
              .summary = "t2::smallest_enclosing_circle_shamos: the farthest-point Delaunay faces (the back half of the T2 complex)",
              .title = "the smallest enclosing circle (Shamos, farthest-point diagram)",
              .time = [](BenchInput& in) -> Timed {
                return [&P = in.points] {
                  return t2::smallest_enclosing_circle_shamos(std::span<const t2::Point>(P)).support.size();
                };
              }});

T2_ALGORITHM({.name = "sec-bt",  // t2 sec --algorithm bt
              .problem = "sec",
              .summary = "t2::smallest_enclosing_circle_bt: Bhattacharya-Toussaint, the hull's diameter, then its farthest-point faces",
              .title = "the smallest enclosing circle (Bhattacharya-Toussaint)",
              .time = [](BenchInput& in) -> Timed {
                return [&P = in.points] {
                  return t2::smallest_enclosing_circle_bt(std::span<const t2::Point>(P)).support.size();
                };
              }});

T2_ALGORITHM({.name = "lec",  // what `t2 lec` runs
              .problem = "lec",
              .summary = "t2::largest_empty_circle: Voronoi vertices in the hull and Voronoi edges across it (Algorithm 13)",
              .title = "the largest empty circle with its centre in the hull",
              .time = [](BenchInput& in) -> Timed {
                return [&P = in.points] {
                  return t2::largest_empty_circle(std::span<const t2::Point>(P)).on_circle.size();
                };
              }});

}  // namespace
}  // namespace t2cli::algorithms
