// Chapter 10: the Delaunay triangulation. The seed's claim that maximising the minimum height
// is the same as maximising the minimum angle, refuted (a counterexample and the rate on random
// convex quadrilaterals); legal edges; Lawson's flips and how many; the randomized incremental
// construction and its flips per point; divide and conquer gives the same triangles; the
// figures of the chapter in both models.
#include "figures.hpp"

#include <t2/t2.hpp>
#include <t2/gen/generate.hpp>
#include <t2/triangulation/delaunay.hpp>
#include <t2/triangulation/divide.hpp>
#include <t2/triangulation/lawson.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

namespace {

namespace dr = t2::draw;
namespace pal = t2::draw::palette;
using t2::Point;
using t2::Triangulation;

void require(bool ok, const char* what) {
  if (!ok) throw std::logic_error(std::string("chapter 10: check failed: ") + what);
}

struct P2 {
  double x, y;
};

//> quality
// The smallest angle and the smallest height of the triangle a b c (doubles: an
// illustration).
double min_angle(P2 a, P2 b, P2 c) {
  auto at = [](P2 o, P2 p, P2 q) {
    return std::abs(std::atan2((p.x - o.x) * (q.y - o.y) - (p.y - o.y) * (q.x - o.x),
                               (p.x - o.x) * (q.x - o.x) + (p.y - o.y) * (q.y - o.y)));
  };
  return std::min({at(a, b, c), at(b, c, a), at(c, a, b)});
}
double min_height(P2 a, P2 b, P2 c) {  // twice the area over the longest side
  const double area2 = std::abs((b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x));
  return area2 /
         std::max({std::hypot(b.x - a.x, b.y - a.y), std::hypot(c.x - b.x, c.y - b.y),
                   std::hypot(a.x - c.x, a.y - c.y)});
}
// Which diagonal of the convex quadrilateral q0 q1 q2 q3 each rule keeps: 0 for q0 q2, 1
// for q1 q3.
int by_angle(const std::array<P2, 4>& q) {
  return std::min(min_angle(q[0], q[1], q[2]), min_angle(q[0], q[2], q[3])) >=
                 std::min(min_angle(q[0], q[1], q[3]), min_angle(q[1], q[2], q[3]))
             ? 0
             : 1;
}
int by_height(const std::array<P2, 4>& q) {
  return std::min(min_height(q[0], q[1], q[2]), min_height(q[0], q[2], q[3])) >=
                 std::min(min_height(q[0], q[1], q[3]), min_height(q[1], q[2], q[3]))
             ? 0
             : 1;
}
//< quality

// The exact Delaunay choice for the counter-clockwise convex quadrilateral: q0 q2 when q3 is
// outside the circle of q0 q1 q2.
int by_circle(const std::array<P2, 4>& q) {
  const Point a = Point::cartesian(q[0].x, q[0].y), b = Point::cartesian(q[1].x, q[1].y),
              c = Point::cartesian(q[2].x, q[2].y), d = Point::cartesian(q[3].x, q[3].y);
  return t2::in_circle(a, b, c, d) < 0 ? 0 : 1;
}

bool convex_ccw(const std::array<P2, 4>& q) {
  for (int i = 0; i < 4; ++i) {
    const P2 a = q[i], b = q[(i + 1) % 4], c = q[(i + 2) % 4];
    if ((b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x) <= 0) return false;
  }
  return true;
}

std::array<P2, 4> counterexample() {
  // The first convex quadrilateral with small integer corners (in this search order) where the
  // rules disagree and both margins are clear, not rounding noise.
  for (int x1 = 1; x1 <= 8; ++x1)
    for (int y3 = 1; y3 <= 8; ++y3)
      for (int x2 = 1; x2 <= 8; ++x2)
        for (int y2 = 1; y2 <= 8; ++y2) {
          const std::array<P2, 4> q{{{0, 0}, {double(x1), 0}, {double(x2), double(y2)}, {0, double(y3)}}};
          if (!convex_ccw(q) || by_angle(q) == by_height(q)) continue;
          const double a0 = std::min(min_angle(q[0], q[1], q[2]), min_angle(q[0], q[2], q[3]));
          const double a1 = std::min(min_angle(q[0], q[1], q[3]), min_angle(q[1], q[2], q[3]));
          const double h0 = std::min(min_height(q[0], q[1], q[2]), min_height(q[0], q[2], q[3]));
          const double h1 = std::min(min_height(q[0], q[1], q[3]), min_height(q[1], q[2], q[3]));
          if (std::abs(a0 - a1) > 0.02 && std::abs(h0 - h1) > 0.02) return q;
        }
  throw std::logic_error("no counterexample");
}

void heights() {
  std::cout << "== max-min angle against max-min height (seed 000, section 5.3.1)\n";
  const auto q = counterexample();
  std::cout << std::fixed << std::setprecision(2);
  //> counterexample
  std::cout << "quadrilateral q0..q3:";
  for (const P2& p : q) std::cout << " (" << p.x << ", " << p.y << ")";
  std::cout << "\n";
  const double deg = 180 / std::acos(-1.0);
  const double a02 =
      std::min(min_angle(q[0], q[1], q[2]), min_angle(q[0], q[2], q[3])) * deg;
  const double a13 =
      std::min(min_angle(q[0], q[1], q[3]), min_angle(q[1], q[2], q[3])) * deg;
  const double h02 = std::min(min_height(q[0], q[1], q[2]), min_height(q[0], q[2], q[3]));
  const double h13 = std::min(min_height(q[0], q[1], q[3]), min_height(q[1], q[2], q[3]));
  std::cout << "diagonal q0 q2: min angle " << a02 << " deg, min height " << h02 << "\n";
  std::cout << "diagonal q1 q3: min angle " << a13 << " deg, min height " << h13 << "\n";
  std::cout << "max-min angle keeps q" << by_angle(q) << " q" << by_angle(q) + 2
            << ", max-min height keeps q" << by_height(q) << " q" << by_height(q) + 2
            << ", the empty circle keeps q" << by_circle(q) << " q" << by_circle(q) + 2
            << "\n";
  //< counterexample
  require(by_angle(q) == by_circle(q) && by_height(q) != by_angle(q), "counterexample");
  //> rate
  std::mt19937_64 rng(10);
  // uniform in [0, 1), exact
  auto u = [](std::mt19937_64& g) { return double(g() >> 11) * 0x1p-53; };
  int convex = 0, differ = 0, angle_not_circle = 0;
  while (convex < 100000) {
    std::array<P2, 4> r;
    for (P2& p : r) p = {u(rng), u(rng)};
    if (!convex_ccw(r)) continue;
    ++convex;
    differ += by_angle(r) != by_height(r);
    angle_not_circle += by_angle(r) != by_circle(r);
  }
  std::cout << "random convex quadrilaterals: " << convex << ", the rules differ on "
            << differ << " (1 in " << std::setprecision(1) << double(convex) / differ
            << ")\n";
  std::cout << "max-min angle against the empty circle: " << angle_not_circle
            << " differences\n";
  //< rate
  std::cout << std::setprecision(2) << "\n";
}

void lawson() {
  std::cout << "== Lawson's flips\n";
  //> lawson-counts
  t2::gen::Options o;
  o.seed = 10;
  for (std::size_t n : {1000, 10000, 100000}) {
    o.n = n;
    const std::vector<Point> P = t2::gen::points(t2::gen::Kind::uniform, o);
    Triangulation tr = t2::triangulate(P);
    const std::size_t flips = t2::flip_to_delaunay(tr);
    const bool same =
        tr.finite_triangles().size() == t2::delaunay(P).finite_triangles().size();
    std::cout << "uniform n = " << n << ": " << flips << " flips (" << double(flips) / n
              << " per point)" << (same ? "" : " DIFFERS") << "\n";
  }
  for (int n : {50, 100, 200}) {  // two rows: the sweep's zigzag needs a quadratic number
    std::vector<Point> P;
    for (int k = 0; k < n; ++k) {
      P.push_back(Point::cartesian(k, 0));
      P.push_back(Point::cartesian(k + 0.5, 1000.0 * n - k));
    }
    Triangulation tr = t2::triangulate(P);
    std::cout << "two rows of " << n << ": " << t2::flip_to_delaunay(tr) << " flips\n";
  }
  //< lawson-counts
  std::cout << "\n";
}

// Counts the flips of the incremental algorithm through its trace hook (t2/trace/hook.hpp).
struct Counting {
  std::size_t* flips;
  void operator()(const t2::trace::Report& r) { *flips += r.event == t2::trace::Event::flip; }
};

void incremental() {
  std::cout << "== the randomized incremental construction: flips per inserted point\n";
  //> incremental-counts
  t2::gen::Options o;
  o.seed = 11;
  for (const char* kind : {"uniform", "normal", "kuzmin"}) {
    o.n = 100000;
    const std::vector<Point> P = t2::gen::points(t2::gen::kind_from_name(kind), o);
    std::size_t flips = 0;
    const std::span<const Point> input(P);
    const Triangulation tr =
        t2::delaunay_with(input, t2::DelaunayTraits{}, Counting{&flips});
    std::cout << kind << ": " << double(flips) / double(P.size()) << " flips per point, "
              << tr.finite_triangles().size() << " triangles\n";
  }
  //< incremental-counts
  std::cout << "\n";
}

void divide() {
  std::cout << "== divide and conquer against the incremental construction\n";
  //> divide-same
  t2::gen::Options o;
  o.seed = 12;
  o.n = 100000;
  for (const char* kind : {"uniform", "kuzmin", "grid", "circle"}) {
    const std::vector<Point> P = t2::gen::points(t2::gen::kind_from_name(kind), o);
    auto a = t2::delaunay_divide(P).finite_triangles();
    auto b = t2::delaunay(P).finite_triangles();
    std::sort(a.begin(), a.end());
    std::sort(b.begin(), b.end());
    std::cout << kind << ": " << a.size() << " triangles, "
              << (a == b ? "the same" : "DIFFERENT") << " for both algorithms\n";
    require(a == b, "divide and conquer and the incremental algorithm agree");
  }
  //< divide-same
  std::cout << "\n";
}

void figures(const std::filesystem::path& dir) {
  dr::FigurePairs out(dir);
  dr::SphereView sphere;
  sphere.lat = 40;
  sphere.lon = -20;
  {  // The counterexample: the Delaunay diagonal (green) and the max-min height one (red, dashed).
    const auto q = counterexample();
    double cx = 0, cy = 0;
    for (const P2& p : q) cx += p.x / 4, cy += p.y / 4;
    std::vector<Point> Q;
    for (const P2& p : q) Q.push_back(Point::cartesian(1.2 * (p.x - cx), 1.2 * (p.y - cy)));
    dr::Figure f;
    f.add(Q, dr::Style().color(pal::blue).width(1.6).fill(pal::blue).fill_opacity(0.08));
    const int a = by_angle(q), h = by_height(q);
    f.add(t2::circle_through(Q[a], Q[a + 1], Q[(a + 2) % 4]), dr::Style().color(pal::light_grey).dash({3, 3}));
    f.segment(Q[a], Q[a + 2], dr::Style().color(pal::green).width(2));
    f.segment(Q[h], Q[h + 2], dr::Style().color(pal::red).width(2).dash({5, 3}));
    for (int k = 0; k < 4; ++k) f.add(Q[k], dr::Style().label("q" + std::to_string(k)));
    dr::PlaneView pv;
    pv.half_width = 3.5;
    out.save(f, "heights", pv, dr::facing(Q, sphere));
  }
  {  // Forty points: the sweep's triangulation and the Delaunay triangulation after the flips.
    t2::gen::Options o;
    o.n = 40;
    o.seed = 3;
    std::vector<Point> P = t2::gen::points(t2::gen::Kind::uniform, o);
    for (Point& p : P) p = Point::cartesian(2 * p.x() / p.w(), 2 * p.y() / p.w());
    dr::PlaneView pv;
    pv.half_width = 3;
    for (const bool flipped : {false, true}) {
      Triangulation tr = t2::triangulate(P);
      if (flipped) t2::flip_to_delaunay(tr);
      dr::Figure f;
      for (const auto& t : tr.finite_triangles())
        f.add(std::vector<Point>{P[t[0]], P[t[1]], P[t[2]]},
              dr::Style().color(pal::blue).fill(pal::blue).fill_opacity(0.08));
      for (const Point& p : P) f.add(p, dr::Style().size(2.5));
      out.save(f, flipped ? "lawson-after" : "lawson-before", pv, dr::facing(P, sphere));
    }
  }
  // Seed 000, figures 5.21 and 5.18 redrawn with the library's T² Delaunay triangulation: points
  // on both sides, and the antipode of a hull vertex added to front points (a flat face).
  // Faces with vertices on both sides (the band across Ω) are shaded orange; the lunes of an
  // antipodal pair and the half great circle between the antipodes are drawn by
  // chapter10::add_antipodal_lunes. Only the points the caption names are labelled, each at a
  // fixed side of its dot (NaN: the first side that is clear). The sphere looks at the
  // antipodal edges when there are any, else at the points (or from longitude `lon`), from
  // latitude `lat`.
  using Labels = std::vector<std::pair<std::size_t, double>>;
  auto t2_figure = [&](const std::vector<Point>& P, const std::string& name, const dr::PlaneView& pv,
                       const Labels& labels, double dot, double lat, double lon = std::nan("")) {
    const Triangulation tr = t2::delaunay(P);
    dr::Figure f;
    for (const auto& t : tr.finite_triangles()) {
      bool flat = false, front = false, back = false;
      for (int k = 0; k < 3; ++k) {
        flat = flat || P[t[k]] == t2::antipode(P[t[(k + 1) % 3]]);
        front = front || P[t[k]].w() > 0;
        back = back || P[t[k]].w() < 0;
      }
      const char* fill = front && back ? pal::orange : pal::blue;
      if (!flat)
        f.add(std::vector<Point>{P[t[0]], P[t[1]], P[t[2]]},
              dr::Style().color(pal::blue).width(1.2).fill(fill).fill_opacity(0.1));
      for (int k = 0; k < 3 && flat; ++k)  // a flat face: only its edges between non-antipodes
        if (!(P[t[k]] == t2::antipode(P[t[(k + 1) % 3]])))
          f.segment(P[t[k]], P[t[(k + 1) % 3]], dr::Style().color(pal::blue).width(1.2));
    }
    const std::vector<Point> middles = chapter10::add_antipodal_lunes(f, tr, P);
    for (const Point& p : P) f.add(p, dr::Style().size(dot).layer(2));
    for (const auto& [k, angle] : labels)
      f.add(P[k], dr::Style().size(dot).label("p" + std::to_string(k)).label_angle(angle).layer(2));
    dr::SphereView v = dr::facing(middles.empty() ? P : middles, sphere);
    if (middles.empty()) v.lat = lat;
    if (!std::isnan(lon)) v.lon = lon;
    out.save(f, name, pv, v);
  };
  {
    t2::gen::Options o;
    o.n = 16;
    o.seed = 4;
    o.back = 0.4;
    dr::PlaneView pv;
    pv.half_width = 1.6;
    t2_figure(t2::gen::points(t2::gen::Kind::both_sides, o), "both-sides", pv, {}, 2.5, 35);
    const std::vector<Point> A = {Point::cartesian(-1, -1), Point::cartesian(1.5, -1), Point::cartesian(0.5, 1.5),
                                  Point::cartesian(0, 0), t2::antipode(Point::cartesian(1.5, -1))};
    pv.half_width = 2.5;
    t2_figure(A, "antipode", pv, {{0, -90}, {1, -60}, {2, 0}, {3, 135}, {4, 30}}, 3.5, 0);
    // Section 8: front points, back points and four directions on Ω (data/examples/omega.t2).
    const std::vector<Point> Z = {
        Point::cartesian(0, 0),        Point::cartesian(0.6, 0.2),     Point::cartesian(-0.3, 0.5),
        Point::cartesian(0.2, -0.6),   Point::cartesian(-0.5, -0.3),   Point::cartesian(0.1, 0.3),
        Point(-1, -0.8, -0.7),         Point(-1, 0.7, -0.6),           Point(-1, -0.5, 0.8),
        Point(-1, 0.2, 0.9),           Point(-1, -0.9, 0.1),           Point::at_infinity(1, 0.36),
        Point::at_infinity(0.5, 0.87), Point::at_infinity(-0.17, 1),   Point::at_infinity(-0.87, 0.5)};
    pv.half_width = 1.6;
    t2_figure(Z, "omega", pv, {{11, 90}, {14, 180}}, 3, 25, -95);  // facing the gap p14 .. p11
  }
  chapter10::more_figures(out);
  std::cerr << out.summary() << "\n";
}

}  // namespace

int main(int argc, char** argv) {
  const std::filesystem::path dir = dr::figures_dir(argc, argv, T2_FIGURES_DIR);
  heights();
  lawson();
  incremental();
  divide();
  figures(dir);
}
