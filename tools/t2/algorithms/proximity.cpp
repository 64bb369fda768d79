// The proximity problems of T² (chapter 12, t2/proximity/), timed by `t2 bench` on points of
// the plane; Kruskal's spanning tree, the divide and conquer closest pair, Welzl's smallest
// enclosing circle and the largest empty circle are animated too (their recorders below). Each but the three `sec` ones (Shamos's builds the whole complex) and `closest-pair-divide`
// builds the Delaunay triangulation of each side in its run, so `t2 bench emst delaunay` compares the whole cost with
// the triangulation's.
#include <fmt/format.h>

#include <gmpxx.h>

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
#include "t2/proximity/union_find.hpp"

namespace t2cli::algorithms {
namespace {

T2_PROBLEM({"emst", "edges", Input::plane});
T2_PROBLEM({"ann", "sites", Input::plane});
T2_PROBLEM({"closest-pair", "pairs", Input::plane});
T2_PROBLEM({"sec", "support sites", Input::plane});
T2_PROBLEM({"lec", "sites on the circle", Input::plane});

namespace tr = t2::trace;

// Past this many points a step's text names no point: each point it names is labelled in both
// pictures, two glyph outlines of about 3 KB in the page, and a spanning tree of 200 points names
// them all (4.4 MB); the step's highlighted edge or sites then say which.
constexpr std::size_t kNamedAtMost = 100;

// "The edge p3-p7", or `unnamed` when there are too many points to name (kNamedAtMost).
std::string edge_name(const Points& P, std::size_t i, std::size_t j, const char* unnamed) {
  return P.size() <= kNamedAtMost ? fmt::format("The edge p{}-p{}", i, j) : std::string(unnamed);
}

// A pair's T² distance in words (pair_distance.hpp): the exact squared length for two sites of
// one side, 0 for equal sites, infinite with a site on Omega, beyond infinity across the sides.
std::string weight_words(const Points& P, std::size_t i, std::size_t j) {
  const t2::Point &a = P[i], &b = P[j];
  if (a == b) return "equal sites, length 0";
  if (a.w() == 0 || b.w() == 0) return "a site on Omega: length infinite";
  if ((a.w() > 0) != (b.w() > 0)) return "opposite sides: length beyond infinity";
  const mpq_class dx = mpq_class(a.x()) / a.w() - mpq_class(b.x()) / b.w(),
                  dy = mpq_class(a.y()) / a.w() - mpq_class(b.y()) / b.w(), l2 = dx * dx + dy * dy;
  const std::string exact = l2.get_str();  // dyadic inputs make long fractions: then a decimal
  return exact.size() <= 24 ? fmt::format("squared length {}", exact) : fmt::format("squared length about {:.6g}", l2.get_d());
}

// The path from i to j along the tree edges (input indices), i first: the cycle an edge i j
// would close.
std::vector<std::size_t> tree_path(const std::vector<tr::Edge>& tree, std::size_t n, std::size_t i, std::size_t j) {
  std::vector<std::vector<std::size_t>> adj(n);
  for (const auto& e : tree) adj[e[0]].push_back(e[1]), adj[e[1]].push_back(e[0]);
  std::vector<std::size_t> from(n, n), todo{j};
  from[j] = j;
  for (std::size_t k = 0; k < todo.size() && from[i] == n; ++k)
    for (std::size_t v : adj[todo[k]])
      if (from[v] == n) from[v] = todo[k], todo.push_back(v);
  std::vector<std::size_t> path{i};
  while (from[i] != n && path.back() != j) path.push_back(from[path.back()]);
  return path;
}

// Kruskal with a recorder: the Delaunay triangulation of each side (its edges are the
// candidates), each edge taken (a lecture step) or dropped (a debugging one), the tree last.
void record_kruskal(const Points& P, const std::string&, tr::Recording& rec) {
  std::vector<tr::Tri> mesh;  // the Delaunay triangles of the sides so far
  std::vector<tr::Edge> tree;
  const auto step = [&](const char* kind, std::string text) {
    tr::Step s = make_step(kind, std::move(text), "tree so far");
    s.triangles = mesh;
    s.edges = tree;
    return s;
  };
  const auto component = [&](const tr::Report& r) {  // the sites of at[0]'s component, read from the forest
    const t2::UnionFind& f = *r.forest;
    std::size_t c = 0;
    for (std::uint32_t k = 0; k < f.size(); ++k) c += f.root(k) == f.root(static_cast<std::uint32_t>(r.at[0]));
    return c;
  };
  const auto hook = [&](const tr::Report& r) {
    if (r.event == tr::Event::candidates) {
      const t2::Triangulation& T = *r.tr;
      const char* side = P[r.input(0)].w() > 0 ? "front" : "back";
      if (T.dimension() == 2) {
        std::size_t edges = 0;
        for (auto h : T.edges()) edges += T.org(h) != t2::Triangulation::infinite && T.dest(h) != t2::Triangulation::infinite;
        for (const auto& f : T.finite_triangles()) mesh.push_back({r.input(f[0]), r.input(f[1]), r.input(f[2])});
        std::sort(mesh.begin(), mesh.end());
        rec.add(step("candidates", fmt::format("The Delaunay triangulation of the {} sites: its {} edges are the "
                                               "candidates, taken by increasing length (the minimum spanning tree "
                                               "is a subgraph of it).",
                                               side, edges)));
      } else {
        rec.add(step("candidates", fmt::format("The {} sites lie on one line: the candidates are consecutive sites "
                                               "along it, taken by increasing length.",
                                               side)));
      }
    } else if (r.event == tr::Event::tree_edge) {
      const std::size_t i = r.at[0], j = r.at[1];
      tree.push_back({i, j});
      tr::Step s = step("take", fmt::format("{} ({}) joins two components: the tree has {} edges, and this "
                                            "component {} sites.",
                                            edge_name(P, i, j, "The edge drawn thick"), weight_words(P, i, j),
                                            tree.size(), component(r)));
      s.chain = {i, j};
      s.points = {i, j};
      rec.add(std::move(s));
    } else if (r.event == tr::Event::cycle_edge) {
      const std::size_t i = r.at[0], j = r.at[1];
      tr::Step s = step("drop", fmt::format("{} ({}) would close a cycle: its ends are already in one component "
                                            "of {} sites, joined by the tree path drawn thick ({} edges).",
                                            edge_name(P, i, j, "The purple edge"), weight_words(P, i, j),
                                            component(r), tree_path(tree, P.size(), i, j).size() - 1));
      s.depth = tr::Depth::debugging;
      s.chain = tree_path(tree, P.size(), i, j);
      s.points = {i, j};
      if (!(P[i] == P[j]) && !(P[i] == t2::antipode(P[j]))) tr::add_segment(s.overlay, P[i], P[j]);
      rec.add(std::move(s));
    }
  };
  const auto answer = t2::minimum_spanning_tree(std::span<const t2::Point>(P), hook);
  tree.clear();
  for (auto [i, j] : answer) tree.push_back({i, j});
  mesh.clear();  // the answer alone
  rec.add(step("answer", P.size() < 2 ? std::string("Fewer than two points: no edge.")
                                      : fmt::format("The minimum spanning tree: {} edges joining the {} points.",
                                                    tree.size(), P.size())));
}

// The answer as a scene: the tree's edges (those that are segments: not between equal or
// antipodal sites).
t2::Scene emst_scene(const Points& P) {
  t2::Scene s;
  for (auto [i, j] : t2::minimum_spanning_tree(std::span<const t2::Point>(P)))
    if (!(P[i] == P[j]) && !(P[i] == t2::antipode(P[j]))) tr::add_segment(s, P[i], P[j]);
  return s;
}

// "[W, X, Y]"
std::string homogeneous(const t2::ExactPoint& c) {
  return fmt::format("[{}, {}, {}]", c.w().get_str(), c.x().get_str(), c.y().get_str());
}

// A circle of the largest empty circle (centre c, through site `site`) and its centre, as an overlay.
t2::Scene lec_scene(const Points& P, const t2::ExactPoint& c, std::size_t site) {
  t2::Scene s;
  const t2::Point centre = t2::to_double(c);
  tr::add_circle(s, t2::Circle(centre, P[site]));
  tr::add_point(s, centre);  // no label: a new one at each candidate would weigh 6 KB a step
  return s;
}

// The answer as a scene: the largest empty circle and its centre.
t2::Scene lec_answer_scene(const Points& P) {
  if (P.empty()) return {};
  const t2::EmptyCircle c = t2::largest_empty_circle(std::span<const t2::Point>(P));
  return lec_scene(P, c.center, c.on_circle.front());
}

// Algorithm 13 with a recorder: each candidate centre a debugging step with its circle, each
// new best a lecture step, the answer last.
void record_lec(const Points& P, const std::string& name, tr::Recording& rec) {
  if (P.empty()) throw t2::BadInput(fmt::format("{}: the largest empty circle needs at least one point", name));
  std::vector<std::size_t> best;  // the sites that define the best circle so far
  const auto hook = [&](const tr::Report& r) {
    if (r.event != tr::Event::empty_circle) return;
    const t2::EmptyCircle& c = *r.circle;
    const std::vector<std::size_t> on(c.on_circle.begin(), c.on_circle.end());
    const std::string exact = c.radius2.get_str();
    const std::string r2 = exact.size() <= 24 ? fmt::format("squared radius {}", exact)
                                              : fmt::format("squared radius about {:.6g}", c.radius2.get_d());
    std::string what;
    const char* kind = "midpoint";
    const bool named = P.size() <= kNamedAtMost;
    if (on.size() == 3) {
      kind = "vertex";
      what = fmt::format("The Voronoi vertex of {}, {}", named ? point_list(on) : "the shaded triangle's sites",
                         homogeneous(c.center));
    } else if (r.at[2] != tr::Report::none) {
      kind = "crossing";
      what = named ? fmt::format("The Voronoi edge of p{} and p{} crosses the hull edge p{}-p{} at {}", r.at[0],
                                 r.at[1], r.at[2], r.at[3], homogeneous(c.center))
                   : fmt::format("The Voronoi edge of the two sites marked crosses the dashed hull edge at {}",
                                 homogeneous(c.center));
    } else {
      what = named ? fmt::format("The midpoint of p{} and p{}, {}", r.at[0], r.at[1], homogeneous(c.center))
                   : fmt::format("The midpoint of the two sites marked, {}", homogeneous(c.center));
    }
    if (r.sign == t2::POSITIVE) best = on;
    tr::Step s = make_step(kind,
                           r.sign == t2::NEGATIVE ? what + ", lies outside the hull: no candidate."
                           : r.sign == t2::POSITIVE
                               ? fmt::format("{}: {}, the largest empty circle so far.", what, r2)
                               : fmt::format("{}: {}, no larger than the best.", what, r2),
                           "best so far");
    s.depth = r.sign == t2::POSITIVE ? tr::Depth::lecture : tr::Depth::debugging;
    s.chain = best;
    s.closed = best.size() == 3;
    s.points = on;
    if (on.size() == 3) s.touched = {tr::Tri{on[0], on[1], on[2]}};
    if (kind == std::string("crossing")) s.edges = {tr::Edge{r.at[2], r.at[3]}};
    s.overlay = lec_scene(P, c.center, on.front());
    rec.add(std::move(s));
  };
  t2::EmptyCircle c;
  try {
    c = t2::largest_empty_circle(std::span<const t2::Point>(P), hook);
  } catch (const t2::UndefinedEmptyCircle& e) {
    throw t2::Undefined(e.site == e.other ? fmt::format("{}: p{}: {}", name, e.site, e.what())
                                          : fmt::format("{}: p{} and p{}: {}", name, e.site, e.other, e.what()));
  }
  const std::vector<std::size_t> on(c.on_circle.begin(), c.on_circle.end());
  tr::Step s = make_step("answer",
                         fmt::format("The largest empty circle: centre {}, squared radius {}, with {} on it.",
                                     homogeneous(c.center), c.radius2.get_str(), point_list(on)),
                         "best so far");
  s.chain = best;
  s.closed = best.size() == 3;
  s.points = on;
  s.overlay = lec_scene(P, c.center, on.front());
  rec.add(std::move(s));
}

// A pair as a scene: the segment between its sites (none when they are equal).
t2::Scene pair_scene(const Points& P, std::pair<std::uint32_t, std::uint32_t> p) {
  t2::Scene s;
  if (!(P[p.first] == P[p.second]) && !(P[p.first] == t2::antipode(P[p.second])))
    tr::add_segment(s, P[p.first], P[p.second]);
  return s;
}

// Shamos and Hoey's divide and conquer with a recorder: each split (its line), each strip and
// each pair compared a debugging step, each new closest pair a lecture step, the pair last.
void record_divide(const Points& P, const std::string& name, tr::Recording& rec) {
  if (!std::all_of(P.begin(), P.end(), [](const t2::Point& p) { return p.w() > 0; }))
    throw t2::BadInput(fmt::format("{}: t2 animate closest-pair-divide takes front points only (w > 0); t2 "
                                   "closest-pair --algorithm divide answers for every input",
                                   name));
  if (P.size() < 2) throw t2::BadInput(fmt::format("{}: the closest pair needs at least two points", name));
  const bool named = P.size() <= kNamedAtMost;
  std::vector<tr::Edge> best;
  const auto vertical = [&](std::size_t m) {  // the line x = x(p_m), upwards
    t2::Scene s;
    tr::add_line(s, P[m], t2::Point(P[m].w(), P[m].x(), P[m].y() + P[m].w()));
    return s;
  };
  const auto hook = [&](const tr::Report& r) {
    const std::vector<std::size_t> sites(r.chain.begin(), r.chain.end());
    const std::string line = named ? fmt::format("the line through p{}", r.at[0]) : std::string("the line drawn");
    tr::Step s;
    if (r.event == tr::Event::split) {
      const auto right = std::find(sites.begin(), sites.end(), r.at[0]) - sites.begin();
      s = make_step("split", fmt::format("Split {} sites (marked) at {}: {} on the left, {} on the right, each half "
                                         "solved first.",
                                         sites.size(), line, right, sites.size() - right),
                    "closest so far");
      s.points = sites;
      s.overlay = vertical(r.at[0]);
    } else if (r.event == tr::Event::strip) {
      s = make_step("strip", fmt::format("The strip: {} sites (marked) near {}, by y; each is compared with those "
                                         "above it that are near enough.",
                                         sites.size(), line),
                    "closest so far");
      s.points = sites;
      s.overlay = vertical(r.at[0]);
    } else if (r.event == tr::Event::compare_pair) {
      const std::size_t a = r.at[0], b = r.at[1];
      const std::string pair = named ? fmt::format("p{}-p{}", a, b) : std::string("The pair drawn thick");
      if (r.sign == t2::POSITIVE) best = {{std::min(a, b), std::max(a, b)}};
      s = make_step("compare",
                    r.sign == t2::POSITIVE
                        ? fmt::format("{} ({}): the closest pair so far.", pair, weight_words(P, a, b))
                        : fmt::format("{} ({}) is no nearer than the closest so far.", pair, weight_words(P, a, b)),
                    "closest so far");
      s.chain = {a, b};
      s.points = {a, b};
    } else {
      return;
    }
    s.depth = r.event == tr::Event::compare_pair && r.sign == t2::POSITIVE ? tr::Depth::lecture : tr::Depth::debugging;
    s.edges = best;
    rec.add(std::move(s));
  };
  const auto p = t2::closest_pair_divide(std::span<const t2::Point>(P), hook);
  tr::Step s = make_step("answer", fmt::format("The closest pair: p{}-p{} ({}).", p.first, p.second,
                                               weight_words(P, p.first, p.second)),
                         "closest so far");
  s.chain = {p.first, p.second};
  s.points = {p.first, p.second};
  s.edges = {{p.first, p.second}};
  rec.add(std::move(s));
}

T2_ALGORITHM({.name = "emst",  // what `t2 emst` runs
              .problem = "emst",
              .summary = "t2::minimum_spanning_tree: Kruskal on the Delaunay edges of each side of T2 (Algorithm 12)",
              .title = "the minimum spanning tree of T2 (Kruskal on the Delaunay edges)",
              .run = emst_scene,
              .record = record_kruskal,
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
              .summary = "t2::closest_pair_divide: Shamos-Hoey divide and conquer on each side of T2 (animated on front points)",
              .title = "the closest pair in T2 (divide and conquer)",
              .run = [](const Points& P) { return pair_scene(P, t2::closest_pair_divide(std::span<const t2::Point>(P))); },
              .record = record_divide,
              .time = [](BenchInput& in) -> Timed {
                return [&P = in.points] {
                  t2::closest_pair_divide(std::span<const t2::Point>(P));
                  return std::size_t(1);
                };
              }});

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
              .run = lec_answer_scene,
              .record = record_lec,
              .time = [](BenchInput& in) -> Timed {
                return [&P = in.points] {
                  return t2::largest_empty_circle(std::span<const t2::Point>(P)).on_circle.size();
                };
              },
              .peers = {"geos"}});

}  // namespace
}  // namespace t2cli::algorithms
