// t2_bench_worker: one measured run of one implementation, for `t2 bench` (tools/t2/cmd_bench.cpp).
//
//   t2_bench_worker PROBLEM IMPL INPUT N SEED
//
// makes N points of INPUT (t2::gen, seeded; not timed), runs IMPL once on them and prints one line
//
//   size=S wall=W cpu=C input_rss_kb=R
//
// S the answer's size (hull vertices, finite triangles), W and C the wall and CPU seconds of the
// run alone, R the peak resident memory once the input was made. `t2 bench` runs every
// measurement in a fresh worker and reads the worker's peak memory from wait4's rusage, so the
// peaks of different runs never add up. This program links CGAL, qhull and GEOS: they are peers of the
// benchmarks, never dependencies of the library or of the `t2` tool.
//
// PROBLEM IMPL: a problem of the registry (tools/t2/algorithms/registry.hpp: hull, layers,
// delaunay, triangulation, hull3d, ...) and an implementation of it: a t2 algorithm registered
// with a timed run (its `time`), or a peer registered in algorithms/peers.cpp, whose run is here:
// cgal (hull, delaunay, hull3d, intersect, locate, locate-build, sec), qhull (hull, hull3d),
// nanoflann and rtree (range: range_peers.hpp), boost (voronoi-front: Boost.Polygon's sweep),
// geos (lec: GEOS's approximate largest empty circle), raw and exact
// (hull, delaunay: t2's own code on plain double predicates, inexact, or on exact arithmetic at
// every call, no filter).
// A problem of space takes points of R^3 (INPUT cube or sphere), one of segments the INPUT
// segments (n segments with exactly n crossings, t2::gen::segments).
// INPUT: a point kind of `t2 gen` (uniform, disk, kuzmin, circle, grid, ...), normal (one
// cluster) or clustered (64 normal clusters). Points are written with w = 1 (circle rounded to
// Cartesian doubles) so that every implementation sees the same doubles.
// Exit status: 0 done; 2 bad arguments; 1 the implementation failed.
#include <sys/resource.h>

#include <CGAL/Delaunay_triangulation_2.h>
#include <boost/polygon/voronoi.hpp>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Min_circle_2.h>
#include <CGAL/Min_circle_2_traits_2.h>
#include <CGAL/Surface_sweep_2_algorithms.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/ch_akl_toussaint.h>
#include <CGAL/convex_hull_3.h>

extern "C" {
#include <libqhull_r/qhull_ra.h>
}
#include <geos_c.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <exception>
#include <functional>
#include <string>
#include <vector>

#include "t2/kernel/filter.hpp"
#include "t2/gen/generate.hpp"
#include "t2/kernel/error.hpp"
#include "t2/hull.hpp"
#include "t2/hull3d.hpp"
#include "t2/kernel/incircle.hpp"
#include "t2/triangulation/delaunay.hpp"
#include "algorithms/answer.hpp"
#include "algorithms/location.hpp"
#include "algorithms/registry.hpp"
#include "range_peers.hpp"
#include "raw_kernel.hpp"

namespace {

using Epick = CGAL::Exact_predicates_inexact_constructions_kernel;
using t2cli::algorithms::finite_count;  // a triangulation's size, counted as t2's runs count it

struct Usage : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// The points of an input, all with w = 1.
std::vector<t2::Point> make_input(const std::string& input, std::size_t n, std::uint64_t seed) {
  t2::gen::Options o;
  o.n = n;
  o.seed = seed;
  o.cartesian = true;  // circle: rounded Cartesian doubles, the same for every implementation
  t2::gen::Kind k;
  if (input == "normal" || input == "clustered") {
    k = t2::gen::Kind::normal;
    o.clusters = input == "normal" ? 1 : 64;
  } else {
    try {
      k = t2::gen::kind_from_name(input);
    } catch (const std::exception& e) {
      throw Usage(e.what());
    }
  }
  std::vector<t2::Point> pts;
  try {
    pts = t2::gen::points(k, o);
  } catch (const std::exception& e) {
    throw Usage(e.what());
  }
  for (auto& p : pts) {
    if (p.w() <= 0) throw Usage("input " + input + " has points off the front side: the peers need front points");
    if (p.w() != 1) p = t2::Point::cartesian(p.x() / p.w(), p.y() / p.w());
  }
  return pts;
}

// The points of a 3-D input (cube, sphere).
std::vector<t2::Point3> make_input3(const std::string& input, std::size_t n, std::uint64_t seed) {
  if (input != "cube" && input != "sphere") throw Usage("hull3d takes the inputs cube and sphere, not " + input);
  t2::gen::Options o;
  o.n = n;
  o.seed = seed;
  std::vector<t2::Point3> P;
  for (const auto& [x, y, z] : t2::gen::points3(t2::gen::kind_from_name(input), o)) P.push_back({x, y, z});
  return P;
}

// The segments of INPUT: for `segments`, n segments with exactly n proper crossings and no other
// contact; else the connected or degenerate kinds of t2::gen (polygon-edges, segment-grid,
// segments-through-point). Every endpoint has w = 1.
std::vector<t2::Segment> make_segments(const std::string& input, std::size_t n, std::uint64_t seed) {
  t2::gen::Kind k{};
  try {
    k = t2::gen::kind_from_name(input);
  } catch (const t2::BadInput&) {
    k = t2::gen::Kind::uniform;
  }
  if (!t2::gen::is_segment_kind(k)) throw Usage("intersect takes a kind of segments, not " + input);
  t2::gen::Options o;
  o.n = n;
  o.crossings = n;
  o.seed = seed;
  return t2::gen::segments(k, o);
}

// The hull by qhull (libqhull_r, default options) of points of dimension `dim` (coordinates one
// after the other): its number of vertices.
std::size_t qhull_hull(std::vector<double>& coords, int dim = 2) {
  qhT qh_storage;
  qhT* qh = &qh_storage;
  QHULL_LIB_CHECK
  qh_zero(qh, stderr);
  char options[] = "qhull";
  const int err =
      qh_new_qhull(qh, dim, static_cast<int>(coords.size()) / dim, coords.data(), False, options, nullptr, stderr);
  const std::size_t h = err == 0 ? static_cast<std::size_t>(qh->num_vertices) : 0;
  qh_freeqhull(qh, !qh_ALL);
  int curlong = 0, totlong = 0;
  qh_memfreeshort(qh, &curlong, &totlong);
  if (err != 0) throw std::runtime_error("qhull failed with error " + std::to_string(err));
  return h;
}

// Orientation on dyadic GMP numbers every time (exact, no filter): with raw_orient
// (raw_kernel.hpp) the two ends of the cost of exactness, for the hull and the Delaunay kernels.
t2::Sign exact_orient(const t2::Point& p, const t2::Point& q, const t2::Point& r) {
  using D = t2::Dyadic;
  return t2::sign_of(
      t2::det3(D(p.w()), D(p.x()), D(p.y()), D(q.w()), D(q.x()), D(q.y()), D(r.w()), D(r.x()), D(r.y())));
}

struct RawHullTraits : t2::HullTraits {
  static t2::Sign orient(const t2::Point& p, const t2::Point& q, const t2::Point& r) { return t2bench::raw_orient(p, q, r); }
};
struct ExactOnlyHullTraits : t2::HullTraits {
  static t2::Sign orient(const t2::Point& p, const t2::Point& q, const t2::Point& r) { return exact_orient(p, q, r); }
};

// The same determinants evaluated exactly (dyadic GMP numbers) on every call: exactness without
// the floating-point filter that makes it cheap.
struct ExactOnlyTraits : t2::DelaunayTraits {
  using D = t2::Dyadic;
  static t2::Sign orient(const t2::Point& p, const t2::Point& q, const t2::Point& r) { return exact_orient(p, q, r); }
  static t2::Sign in_circle(const t2::Point& a, const t2::Point& b, const t2::Point& c, const t2::Point& d) {
    return t2::sign_of(t2::detail::lifted_det4(D(a.w()), D(a.x()), D(a.y()), D(b.w()), D(b.x()), D(b.y()), D(c.w()),
                                               D(c.x()), D(c.y()), D(d.w()), D(d.x()), D(d.y())));
  }
};

double cpu_now() {
  timespec ts{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
  return double(ts.tv_sec) + 1e-9 * double(ts.tv_nsec);
}

long rss_kb() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return u.ru_maxrss;
}

// A prepared run: the conversion a peer needs is made before the clock starts.
using Run = std::function<std::size_t()>;

// The runs of the peers (algorithms/peers.cpp) on each problem; nullptr when it has none.
Run hull_peer(const std::string& impl, const std::vector<t2::Point>& P) {
  if (impl == "raw") return [&P] { return t2::convex_hull<RawHullTraits>(P).size(); };
  if (impl == "exact") return [&P] { return t2::convex_hull<ExactOnlyHullTraits>(P).size(); };
  if (impl == "cgal") {
    auto C = std::make_shared<std::vector<Epick::Point_2>>(t2bench::to_cgal(P));
    return [C] {
      std::vector<Epick::Point_2> out;
      CGAL::ch_akl_toussaint(C->begin(), C->end(), std::back_inserter(out));
      return out.size();
    };
  }
  if (impl == "qhull") {
    auto xy = std::make_shared<std::vector<double>>();
    xy->reserve(2 * P.size());
    for (const auto& p : P) xy->insert(xy->end(), {p.x(), p.y()});
    return [xy] { return qhull_hull(*xy); };
  }
  return nullptr;
}

Run delaunay_peer(const std::string& impl, std::vector<t2::Point>& P) {
  if (impl == "raw") return [&P] { return finite_count(t2::delaunay_with<t2bench::RawDelaunayTraits>(P)); };
  if (impl == "exact") return [&P] { return finite_count(t2::delaunay_with<ExactOnlyTraits>(P)); };
  if (impl == "cgal") {
    auto C = std::make_shared<std::vector<Epick::Point_2>>(t2bench::to_cgal(P));
    return [C] {
      CGAL::Delaunay_triangulation_2<Epick> dt;
      dt.insert(C->begin(), C->end());
      return dt.number_of_faces();
    };
  }
  return nullptr;
}

Run hull3d_peer(const std::string& impl, const std::vector<t2::Point3>& P) {
  if (impl == "cgal") {
    auto C = std::make_shared<std::vector<Epick::Point_3>>();
    for (const auto& p : P) C->emplace_back(p.x, p.y, p.z);
    return [C] {
      CGAL::Surface_mesh<Epick::Point_3> m;
      CGAL::convex_hull_3(C->begin(), C->end(), m);
      return static_cast<std::size_t>(m.number_of_vertices());
    };
  }
  if (impl == "qhull") {
    auto xyz = std::make_shared<std::vector<double>>();
    for (const auto& p : P) xyz->insert(xyz->end(), {p.x, p.y, p.z});
    return [xyz] { return qhull_hull(*xyz, 3); };
  }
  return nullptr;
}

// CGAL's surface sweep on the exact kernel (its intersection points are constructed exactly),
// without the endpoints: on `segments` input every crossing is proper, so it counts what t2
// counts.
Run intersect_peer(const std::string& impl, const std::vector<t2::Segment>& S) {
  if (impl != "cgal") return nullptr;
  using Epeck = CGAL::Exact_predicates_exact_constructions_kernel;
  auto C = std::make_shared<std::vector<Epeck::Segment_2>>();
  for (const auto& s : S)
    C->emplace_back(Epeck::Point_2(s.source().x() / s.source().w(), s.source().y() / s.source().w()),
                    Epeck::Point_2(s.target().x() / s.target().w(), s.target().y() / s.target().w()));
  return [C] {
    std::vector<Epeck::Point_2> out;
    CGAL::compute_intersection_points(C->begin(), C->end(), std::back_inserter(out), false);
    return out.size();
  };
}

// CGAL's Delaunay_triangulation_2<Epick> of the points, then its locate of the queries of t2's
// walk (locate_queries: random order for cgal, spatial order for cgal-sorted), each from the
// face of the answer before: the number of queries in the closed hull, as t2's walk counts them.
Run locate_peer(const std::string& impl, const std::vector<t2::Point>& P) {
  if (impl != "cgal" && impl != "cgal-sorted") return nullptr;
  using Dt = CGAL::Delaunay_triangulation_2<Epick>;
  auto dt = std::make_shared<Dt>();
  const auto C = t2bench::to_cgal(P);
  dt->insert(C.begin(), C.end());
  auto Q = std::make_shared<std::vector<Epick::Point_2>>();
  for (const auto& q : t2cli::algorithms::locate_queries(P, impl == "cgal-sorted")) Q->emplace_back(q.x() / q.w(), q.y() / q.w());
  return [dt, Q] {
    std::size_t inside = 0;
    Dt::Face_handle hint;
    for (const auto& q : *Q) {
      Dt::Locate_type lt;
      int li = 0;
      hint = dt->locate(q, lt, li, hint);
      inside += lt != Dt::OUTSIDE_CONVEX_HULL && lt != Dt::OUTSIDE_AFFINE_HULL;
    }
    return inside;
  };
}

// CGAL's preprocessing for locate: Delaunay_triangulation_2<Epick> of the points, its number of
// finite faces (t2's locate-build counts the faces of its map, the same triangles).
Run locate_build_peer(const std::string& impl, const std::vector<t2::Point>& P) {
  if (impl != "cgal") return nullptr;
  auto C = std::make_shared<std::vector<Epick::Point_2>>(t2bench::to_cgal(P));
  return [C] {
    CGAL::Delaunay_triangulation_2<Epick> dt(C->begin(), C->end());
    return static_cast<std::size_t>(dt.number_of_faces());
  };
}

// CGAL's Min_circle_2 on the exact kernel (Epeck: its circumcentres are constructed exactly),
// randomized (its own shuffle, CGAL's default random): the number of support points.
Run sec_peer(const std::string& impl, const std::vector<t2::Point>& P) {
  if (impl != "cgal") return nullptr;
  using Epeck = CGAL::Exact_predicates_exact_constructions_kernel;
  auto C = std::make_shared<std::vector<Epeck::Point_2>>();
  C->reserve(P.size());
  for (const auto& p : P) C->emplace_back(p.x(), p.y());  // w = 1 (make_input)
  return [C] {
    CGAL::Min_circle_2<CGAL::Min_circle_2_traits_2<Epeck>> mc(C->begin(), C->end(), true);
    return static_cast<std::size_t>(mc.number_of_support_points());
  };
}

// Boost.Polygon's sweep (construct_voronoi), which takes 32-bit integer points only: the
// doubles rounded to the grid 2^-24 (inputs within [-64, 64), as `t2 gen` makes them; not
// timed). Its vertex count is the front vertices' of the rounded points, so it need not equal
// Fortune's (Peer::exact is false).
Run voronoi_peer(const std::string& impl, const std::vector<t2::Point>& P) {
  if (impl != "boost") return nullptr;
  auto B = std::make_shared<std::vector<boost::polygon::point_data<int>>>();
  B->reserve(P.size());
  for (const auto& p : P)  // w = 1 (make_input)
    B->emplace_back(static_cast<int>(std::lround(std::ldexp(p.x(), 24))),
                    static_cast<int>(std::lround(std::ldexp(p.y(), 24))));
  return [B] {
    boost::polygon::voronoi_diagram<double> vd;
    boost::polygon::construct_voronoi(B->begin(), B->end(), &vd);
    return vd.num_vertices();
  };
}

// GEOS's largest empty circle (GEOSLargestEmptyCircle_r: a grid refined by branch and bound, its
// centre in the obstacles' hull as t2's, found to within a tolerance, in doubles): the points as
// one MultiPoint (made before the clock), the tolerance a thousandth of the mean spacing of the
// points, sqrt(area of their box / n). Not exact (Peer::exact is false): its size is 1, the circle.
Run lec_peer(const std::string& impl, const std::vector<t2::Point>& P) {
  if (impl != "geos" || P.empty()) return nullptr;
  struct Geos {
    GEOSContextHandle_t h = GEOS_init_r();
    GEOSGeometry* points = nullptr;
    ~Geos() {
      if (points != nullptr) GEOSGeom_destroy_r(h, points);
      GEOS_finish_r(h);
    }
  };
  auto g = std::make_shared<Geos>();
  std::vector<GEOSGeometry*> each;
  double x0 = P[0].x(), x1 = x0, y0 = P[0].y(), y1 = y0;
  for (const auto& p : P) {  // w = 1 (make_input)
    each.push_back(GEOSGeom_createPointFromXY_r(g->h, p.x(), p.y()));
    x0 = std::min(x0, p.x()), x1 = std::max(x1, p.x()), y0 = std::min(y0, p.y()), y1 = std::max(y1, p.y());
  }
  g->points = GEOSGeom_createCollection_r(g->h, GEOS_MULTIPOINT, each.data(), static_cast<unsigned>(each.size()));
  const double tolerance = 1e-3 * std::sqrt((x1 - x0) * (y1 - y0) / static_cast<double>(P.size()));
  return [g, tolerance]() -> std::size_t {
    GEOSGeometry* circle = GEOSLargestEmptyCircle_r(g->h, g->points, nullptr, tolerance);
    if (circle == nullptr) throw std::runtime_error("GEOS found no largest empty circle");
    GEOSGeom_destroy_r(g->h, circle);
    return 1;
  };
}

// The run of IMPL on PROBLEM's input: a registered t2 algorithm's, else a peer's.
Run prepare(const std::string& problem, const std::string& impl, t2cli::algorithms::BenchInput& in) {
  namespace reg = t2cli::algorithms;
  if (const reg::Algorithm* a = reg::find(impl); a != nullptr && a->time && a->problem == problem) return a->time(in);
  Run run;
  if (const reg::Peer* f = reg::find_peer(impl);
      f != nullptr && std::find(f->problems.begin(), f->problems.end(), problem) != f->problems.end())
    run = problem == "hull"       ? hull_peer(impl, in.points)
          : problem == "delaunay" ? delaunay_peer(impl, in.points)
          : problem == "hull3d"   ? hull3d_peer(impl, in.points3)
          : problem == "intersect" ? intersect_peer(impl, in.segments)
          : problem == "locate"   ? locate_peer(impl, in.points)
          : problem == "locate-build" ? locate_build_peer(impl, in.points)
          : problem == "sec"      ? sec_peer(impl, in.points)
          : problem == "range"    ? t2bench::range_peer(impl, in.points)
          : problem == "voronoi-front" ? voronoi_peer(impl, in.points)
          : problem == "lec"      ? lec_peer(impl, in.points)
                                  : nullptr;
  if (!run) throw Usage("no implementation " + impl + " of " + problem);
  return run;
}

int work(int argc, char** argv) {
  if (argc != 6) throw Usage("usage: t2_bench_worker PROBLEM IMPL INPUT N SEED");
  const std::string problem = argv[1], impl = argv[2], input = argv[3];
  std::size_t n = 0;
  std::uint64_t seed = 0;
  try {
    n = std::stoull(argv[4]);
    seed = std::stoull(argv[5]);
  } catch (const std::exception&) {
    throw Usage("N and SEED are non-negative integers");
  }
  const t2cli::algorithms::Problem* pr = t2cli::algorithms::find_problem(problem);
  if (pr == nullptr) throw Usage("unknown problem " + problem);
  t2cli::algorithms::BenchInput in;  // "owned" hands its points to the result
  // CGAL reports shared endpoints by its own rule (its `report_endpoints` flag: none, or every
  // endpoint), not t2's (an endpoint on two or more segments): its count is t2's only where no
  // two segments touch at an endpoint.
  if (problem == "intersect" && impl == "cgal" && input != "segments")
    throw Usage("cgal counts shared endpoints by another rule than t2: time it on --input segments "
                "(on " + input + ", --vs intersect-circular,intersect-brute)");
  if (pr->input == t2cli::algorithms::Input::space)
    in.points3 = make_input3(input, n, seed);
  else if (pr->input == t2cli::algorithms::Input::segments)
    in.segments = make_segments(input, n, seed);
  else
    in.points = make_input(input, n, seed);
  const Run run = prepare(problem, impl, in);
  const long input_rss = rss_kb();
  const auto w0 = std::chrono::steady_clock::now();
  const double c0 = cpu_now();
  const std::size_t size = run();  // the answer is destroyed inside: its memory is in the peak
  const double cpu = cpu_now() - c0;
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - w0).count();
  std::printf("size=%zu wall=%.9g cpu=%.9g input_rss_kb=%ld\n", size, wall, cpu, input_rss);
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  try {
    return work(argc, argv);
  } catch (const Usage& e) {
    std::fprintf(stderr, "t2_bench_worker: %s\n", e.what());
    return 2;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "t2_bench_worker: %s\n", e.what());
    return 1;
  }
}
