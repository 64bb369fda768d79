// Chapter 14: point location in a subdivision of T². The half-edge structure of a map whose
// faces cross Ω, the walk of seed 000's Algorithm 15 with the regions it crosses, its degenerate
// cases, and the walk checked against testing every face; the trapezoidal maps, their answers and
// their sizes; the figures in both models (figures.cpp).
#include <t2/draw.hpp>
#include <t2/kernel/point_in_polygon.hpp>
#include <t2/location/trapezoid_locate.hpp>
#include <t2/location/walk.hpp>
#include <t2/triangulation/delaunay.hpp>
#include <t2/t2.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include "figures.hpp"

namespace {

using t2::Location;
using t2::Point;
using t2::Subdivision;
using Index = Subdivision::Index;

void require(bool ok, const char* what) {
  if (!ok) throw std::logic_error(std::string("chapter 14: check failed: ") + what);
}

std::string region(Index f) { return f == Subdivision::outside ? "out" : "F" + std::to_string(f); }

// The vertex of S equal to p.
Index vertex(const Subdivision& S, const Point& p) {
  for (Index v = 0; v < S.points().size(); ++v)
    if (S.points()[v] == p) return v;
  throw std::logic_error("chapter 14: not a vertex");
}

void structure() {
  std::cout << "== the half-edges of the fan map\n";
  //> map-demo
  const Subdivision S(chapter14::fan_map());
  std::cout << S.faces() << " faces, " << S.points().size() << " vertices, "
            << S.half_edges() << " half-edges, " << S.boundary().size()
            << " on the complement\n";
  for (Index f = 0; f < S.faces(); ++f) {
    std::cout << "F" << f << ":";
    for (Index h = S.first(f); h < S.first(f) + S.size(f); ++h)
      std::cout << "  " << h << " " << t2::to_string(S.points()[S.org(h)]) << " "
                << (S.twin(h) == Subdivision::none ? "out"
                                                   : "~" + std::to_string(S.twin(h)));
    std::cout << "\n";
  }
  //< map-demo
  const Index a = vertex(S, Point(1, 1, 0));
  std::cout << "corners at [1, 1, 0]:";
  for (const auto& c : S.corners(a)) std::cout << " F" << c.face << "/" << c.k;
  std::cout << "\n\n";
}

void walks() {
  std::cout << "== walks: the regions crossed from q to p\n";
  const Subdivision S(chapter14::fan_map());
  //> walk-demo
  const struct { Point q, p; } W[] = {
      {Point(1, 0, 0), Point(-2, 4, 1)},    // O to a back point of F4, through Ω
      {Point(1, 0, 0), Point(2, 5, 0)},     // O along the edge to a, then on
      {Point(1, 0, 1), Point(-1, 0, -1)},   // b to its antipode
      {Point(1, 0, 0), Point(-1, -3, 1)}};  // into the complement, on the back
  for (const auto& w : W) {
    std::vector<Index> crossed;
    const Location l = t2::walk(S, w.p, vertex(S, w.q), &crossed);
    std::cout << t2::to_string(w.q) << " -> " << t2::to_string(w.p) << ": ";
    std::cout << t2::to_string(l) << " via";
    for (const Index f : crossed) std::cout << " " << region(f);
    std::cout << "\n";
    require(l == t2::locate_brute(S, w.p), "walk = brute on the four walks");
  }
  //< walk-demo
  std::cout << "\n";
}

void degenerate() {
  std::cout << "== queries on vertices, edges, Ω and the back\n";
  const Subdivision S(chapter14::fan_map());
  //> degenerate-demo
  const Point Q[] = {Point(1, 1, 0),  Point(2, 1, 1),  Point(0, 1, 1),  Point(0, 2, 1),
                     Point(-1, 1, 1), Point(-1, 3, 3), Point(0, -1, 0), Point(-1, 0, 0)};
  for (const Point& p : Q) {
    const Location walked = t2::walk(S, p, 0), tested = t2::locate_brute(S, p);
    std::cout << t2::to_string(p) << ": " << t2::to_string(walked) << "\n";
    require(walked == tested, "walk = brute on the degenerate queries");
  }
  //< degenerate-demo
  std::cout << "\n";
}

// A map the checks accept although it is not a subdivision: a vertex of F1 inside an edge of F0.
void t_junction() {
  std::cout << "== a T-junction\n";
  //> t-junction-demo
  const auto at = [](double x, double y) { return Point::cartesian(x, y); };
  const std::vector<t2::Polygon> F{{at(0, 0), at(4, 0), at(0, 4)},
                                   {at(2, 0), at(0, -2), at(4, -2)}};
  const Subdivision S(F);  // accepted: the two faces share no vertex
  const Point p = at(2, 0);
  std::cout << "walk: " << t2::to_string(t2::walk(S, p, vertex(S, at(0, -2))))
            << ", every face tested: " << t2::to_string(t2::locate_brute(S, p)) << "\n";
  //< t-junction-demo
  std::cout << "\n";
}

// A non-convex face entered many times: a comb of m teeth, crossed by a segment through all of
// them, from a vertex of a triangle beside it.
void comb() {
  std::cout << "== a comb\n";
  //> comb-demo
  const auto at = [](double x, double y) { return Point(8, x, y); };  // in eighths
  const int m = 6;
  const t2::Polygon comb = chapter14::comb(m);  // tooth i: x from 2i to 2i + 1, up to y = 2
  const Subdivision S(std::vector<t2::Polygon>{comb, chapter14::comb_start()});
  std::vector<Index> crossed;
  const Location l = t2::walk(S, at(2 * m + 1, 1.5), vertex(S, at(-1, 1.5)), &crossed);
  const auto times = [&](Index r) { return std::count(crossed.begin(), crossed.end(), r); };
  std::cout << t2::to_string(l) << ": the comb (" << comb.size() << " edges) entered "
            << times(0) << " times, the complement (" << S.boundary().size() << " edges) "
            << times(Subdivision::outside) << " times\n";
  //< comb-demo
  require(times(0) == m && times(Subdivision::outside) == m + 1, "the comb");
  std::cout << "\n";
}

// Random queries on the front, the back and Ω, and points exactly inside edges, from every
// start vertex: the walk against every face tested; and no point strictly inside two faces.
void random_check() {
  std::cout << "== the walk against testing every face\n";
  const auto F = chapter14::fan_map();
  const Subdivision S(F);
  std::mt19937_64 rng(14);
  std::uniform_int_distribution<int> c(-8, 8);
  std::vector<Point> Q;
  for (int i = 0; i < 3000; ++i) {  // back, Ω, front
    const int x = c(rng), y = c(rng);
    if (i % 3 != 1 || x != 0 || y != 0) Q.emplace_back(i % 3 - 1, x, y);
  }
  for (Index h = 0; h < S.half_edges(); ++h) {  // the sum of the two ends: inside the edge
    const Point &a = S.points()[S.org(h)], &b = S.points()[S.dest(h)];
    Q.emplace_back(a.w() + b.w(), a.x() + b.x(), a.y() + b.y());
  }
  int agree = 0, total = 0, overlaps = 0;
  for (const Point& p : Q) {
    int inside = 0;
    for (const auto& f : F) inside += t2::locate(f, p) == t2::POSITIVE;
    overlaps += inside > 1;
    const Location l = t2::locate_brute(S, p);
    for (Index v = 0; v < S.points().size(); ++v, ++total) agree += t2::walk(S, p, v) == l;
  }
  std::cout << Q.size() << " queries from each of the " << S.points().size() << " vertices:\n"
            << "the walk agrees with the test of every face " << agree << " times out of " << total
            << "\npoints inside two faces: " << overlaps << "\n";
  require(agree == total && overlaps == 0, "random queries");
}

// The number of trapezoids of the final map.
std::size_t live(const t2::TrapezoidMap& M) {
  std::size_t n = 0;
  for (const auto& t : M.trapezoids()) n += t.node != t2::TrapezoidMap::none;
  return n;
}

// Two squares on the front (a vertical edge shared, vertices in a column at x = 2) and a
// triangle on the back: both charts closed; the trapezoidal maps against the walk.
void trapezoids() {
  std::cout << "== the trapezoidal maps\n";
  //> trapezoid-demo
  const auto at = [](double x, double y) { return Point::cartesian(x, y); };
  const std::vector<t2::Polygon> F{
      {at(0, 0), at(2, 0), at(2, 2), at(0, 2)},                    // F0
      {at(2, 0), at(4, 0), at(4, 2), at(2, 2)},                    // F1
      {Point(-1, 0, 0), Point(-1, 0, -1), Point(-1, -1, 0)}};      // F2, on the back
  const Subdivision S(F);
  const t2::TrapezoidLocator L(S);
  for (const auto side : {t2::TrapezoidLocator::front, t2::TrapezoidLocator::back}) {
    const t2::TrapezoidMap& M = *L.chart(side);
    std::cout << (side == t2::TrapezoidLocator::front ? "front" : "back") << ": "
              << M.segments() << " segments, " << live(M) << " trapezoids, "
              << M.nodes() << " DAG nodes, depth " << M.depth() << "\n";
  }
  const Point Q[] = {at(1, 1), at(2, 1), at(2, 2), at(2, 3), at(3, 1),
                     Point(-4, -1, -1), Point(-2, -1, 0), Point(0, 1, 0)};
  for (const Point& p : Q) {
    const Location l = L.locate(p);
    std::cout << t2::to_string(p) << ": " << t2::to_string(l) << "\n";
    require(l == t2::walk(S, p, 0), "the trapezoidal maps answer as the walk");
  }
  //< trapezoid-demo
  std::cout << "\n";
}

// The size and the paths of the DAG on Delaunay maps of random points (measured, one order).
void trapezoid_sizes() {
  std::cout << "== the DAG on Delaunay maps (one random order each)\n";
  std::mt19937_64 rng(8);
  std::uniform_real_distribution<double> d(0, 1);
  for (const int n : {1000, 10000, 100000}) {
    std::vector<Point> P;
    for (int i = 0; i < n; ++i) {
      const double x = d(rng), y = d(rng);  // in this order, on every compiler
      P.push_back(Point::cartesian(x, y));
    }
    std::vector<std::vector<Index>> F;
    for (const auto& t : t2::delaunay(P).finite_triangles()) F.push_back({t[0], t[1], t[2]});
    const Subdivision S(P, F);
    const t2::TrapezoidLocator L(S);
    const t2::TrapezoidMap& M = *L.chart(t2::TrapezoidLocator::front);
    double steps = 0, H = 0;
    for (int i = 0; i < 10000; ++i) {
      const double x = d(rng), y = d(rng);
      steps += double(M.locate(Point::cartesian(x, y)).steps);
    }
    for (std::size_t i = 1; i <= M.segments(); ++i) H += 1.0 / double(i);
    std::cout << "n = " << M.segments() << " segments: " << double(M.nodes()) / double(M.segments())
              << " nodes per segment, " << double(live(M)) / double(M.segments())
              << " trapezoids per segment, depth " << M.depth() << ", mean path " << steps / 10000
              << " (1 + 12 H_n = " << 1 + 12 * H << ")\n";
    require(double(M.nodes()) <= 20.0 * double(M.segments()) && steps / 10000 <= 1 + 12 * H, "DAG bounds");
  }
  std::cout << "\n";
}

}  // namespace

int main(int argc, char** argv) {
  const std::filesystem::path dir = t2::draw::figures_dir(argc, argv, T2_FIGURES_DIR);
  structure();
  walks();
  degenerate();
  t_junction();
  comb();
  random_check();
  trapezoids();
  trapezoid_sizes();
  chapter14::figures(dir);
}
