// Chapter 06: convex hulls in T². Hull existence (seed 000, Algorithm 3), the five algorithms of
// t2/hull.hpp on one set that crosses Ω, degenerate input, sets without a hull and the points
// that prove it, the sorting lower bound, and the figures of the chapter in both models.
#include <t2/gen/generate.hpp>
#include <t2/hull.hpp>
#include <t2/t2.hpp>

#include <algorithm>
#include <filesystem>
#include <iostream>
#include <stdexcept>
#include <string>
#include <vector>

namespace {

namespace dr = t2::draw;
namespace pal = t2::draw::palette;
using t2::HullAlgorithm;
using t2::Point;

void require(bool ok, const char* what) {
  if (!ok) throw std::logic_error(std::string("chapter 06: check failed: ") + what);
}

std::string indices(const std::vector<std::size_t>& h) {
  std::string s;
  for (std::size_t i : h) s += " p" + std::to_string(i);
  return s;
}

// Two cycles of indices are the same up to rotation (the points are distinct here).
bool same_cycle(std::vector<std::size_t> a, const std::vector<std::size_t>& b) {
  if (a.size() != b.size()) return false;
  for (std::size_t r = 0; r < a.size(); ++r) {
    if (a == b) return true;
    std::rotate(a.begin(), a.begin() + 1, a.end());
  }
  return a.empty();
}

const std::vector<HullAlgorithm> kAlgorithms{HullAlgorithm::merge, HullAlgorithm::jarvis, HullAlgorithm::graham,
                                             HullAlgorithm::quickhull, HullAlgorithm::monotone};

// A set on both sides of T² and on Ω: front points on the left, back points drawn on the
// right, one point at infinity. All lie in the open hemisphere 2w − x > 0.
std::vector<Point> crossing_set() {
  //> crossing-set
  return {Point::cartesian(-2, 0), Point::cartesian(-1, -1.5), Point::cartesian(-0.5, 0.5),
          Point::cartesian(0, 2),  Point(-1, -3, 1),            Point(-1, -2.5, -1.5),
          Point(-1, -4, 0),        Point(0, -1, 0.25),          Point::cartesian(-1, 1)};
  //< crossing-set
}

void every_algorithm() {
  std::cout << "== the five algorithms on a set that crosses Omega\n";
  //> hull-demo
  const std::vector<Point> A = crossing_set();
  const std::vector<std::size_t> ref = t2::convex_hull(A, HullAlgorithm::merge);
  for (HullAlgorithm a : kAlgorithms) {
    const std::vector<std::size_t> h = t2::convex_hull(A, a);
    std::cout << t2::name(a) << ":" << indices(h)
              << (same_cycle(h, ref) ? "" : "   DIFFERS") << "\n";
  }
  //< hull-demo
  for (HullAlgorithm a : kAlgorithms) require(same_cycle(t2::convex_hull(A, a), ref), "algorithms agree");
  // Every hull edge has every point on its left or on it (the definition of the hull).
  for (std::size_t k = 0; k < ref.size(); ++k)
    for (const Point& p : A) require(t2::orient(A[ref[k]], A[ref[(k + 1) % ref.size()]], p) >= 0, "hull edge");
  std::cout << "every point left of or on every hull edge: true\n\n";
}

void degenerate() {
  std::cout << "== degenerate input\n";
  //> degenerate
  const std::vector<Point> D{Point::cartesian(0, 0), Point::cartesian(4, 0),
                             Point::cartesian(2, 0),  // collinear
                             Point(2, 8, 0),          // (4, 0) again, scaled by 2
                             Point::cartesian(4, 4), Point::cartesian(0, 4),
                             Point::cartesian(2, 2)};
  std::cout << "square with an edge point, a repeated corner and a centre:"
            << indices(t2::convex_hull(D)) << "\n";
  const std::vector<Point> L{Point::cartesian(1, 1), Point::cartesian(3, 2),
                             Point(0, 2, 1), Point(-1, 3, 1)};
  std::cout << "(1,1), (3,2), their line's point at infinity and the back point [-1, 3, 1]:"
            << indices(t2::convex_hull(L)) << "\n";
  try {
    t2::convex_hull(std::vector<Point>{L[0], L[1], L[2], Point(-1, -5, -3)});
  } catch (const t2::NoHull& e) {
    std::cout << "with [-1, -5, -3] instead: " << e.what() << "\n";
  }
  //< degenerate
  std::cout << "\n";
}

void no_hull() {
  std::cout << "== sets without a hull\n";
  //> no-hull
  const std::vector<std::vector<Point>> sets{
      {Point::cartesian(0, 0), Point::cartesian(2, 1),
       Point(-1, -2, -1)},  // p1 and p2 antipodal
      {Point(0, 1, 0), Point(0, -1, 2),
       Point(0, -1, -2)},  // three directions all round Ω
      {Point::cartesian(-2, -1), Point::cartesian(2, -1), Point::cartesian(0, 2),
       Point(-1, 0, 0)},  // ¬p3 in the triangle
  };
  for (const auto& S : sets) {
    try {
      t2::convex_hull(S);
      std::cout << "a hull?\n";
    } catch (const t2::NoHull& e) {
      std::cout << e.what() << "\n";
    }
  }
  //< no-hull
  for (const auto& S : sets) require(!t2::has_hull<t2::HullTraits>(S), "no hull");
  std::cout << "\n";
}

void lower_bound() {
  std::cout << "== sorting with a hull\n";
  //> sorting
  const std::vector<double> x{7, -3, 12, 0.5, -8, 4, 9, -1};
  std::vector<Point> P;
  for (double v : x) P.push_back(Point::cartesian(v, v * v));  // on the parabola y = x²
  std::vector<std::size_t> h = t2::convex_hull(P);             // every point is a vertex
  std::rotate(
      h.begin(),
      std::min_element(h.begin(), h.end(), [&](auto a, auto b) { return x[a] < x[b]; }),
      h.end());
  std::cout << "sorted:";
  for (std::size_t i : h) std::cout << " " << x[i];
  std::cout << "\n";
  //< sorting
  require(std::is_sorted(h.begin(), h.end(), [&](auto a, auto b) { return x[a] < x[b]; }) && h.size() == x.size(),
          "the hull sorts");
  std::cout << "\n";
}

void generated() {
  std::cout << "== generated input (t2 gen), every algorithm\n";
  for (const char* kind : {"uniform", "circle", "grid", "duplicates", "both-sides", "infinity"}) {
    t2::gen::Options o;
    o.n = 2000;
    o.seed = 6;
    const auto P = t2::gen::points(t2::gen::kind_from_name(kind), o);
    const auto ref = t2::convex_hull(P, HullAlgorithm::merge);
    bool agree = true;
    for (HullAlgorithm a : kAlgorithms) {
      std::vector<Point> got, want;
      for (std::size_t i : t2::convex_hull(P, a)) got.push_back(P[i]);
      for (std::size_t i : ref) want.push_back(P[i]);
      agree = agree && got.size() == want.size() &&
              std::all_of(got.begin(), got.end(), [&](const Point& p) { return std::find(want.begin(), want.end(), p) != want.end(); });
    }
    require(agree, "generated input");
    std::cout << kind << ": " << P.size() << " points, " << ref.size() << " hull vertices, all five agree\n";
  }
  std::cout << "\n";
}

void figures(const std::filesystem::path& dir) {
  dr::FigurePairs out(dir);
  const dr::Style hull_style = dr::Style().fill(pal::green).fill_opacity(0.2).color(pal::green).width(1.6);
  dr::PlaneView plane;
  plane.half_width = 5;
  dr::SphereView sphere;
  sphere.lat = 25;
  sphere.lon = -20;
  {  // The hull of the crossing set: it leaves the front through Ω and comes back from behind.
    const auto A = crossing_set();
    std::vector<Point> hull;
    for (std::size_t i : t2::convex_hull(A)) hull.push_back(A[i]);
    dr::Figure f;
    f.add(hull, hull_style);
    for (std::size_t i = 0; i < A.size(); ++i) f.add(A[i], dr::Style().label("p" + std::to_string(i)));
    dr::SphereView above;  // from the centre of the hemisphere 2w − x > 0, tilted down
    above.lat = 35;
    above.lon = 180;
    out.save(f, "crossing", plane, above);
  }
  {  // No hull: p0, p1, p2 front, p3 the back point whose antipode is inside their triangle.
    const std::vector<Point> B{Point::cartesian(-2, -1), Point::cartesian(2, -1), Point::cartesian(0, 2), Point(-1, 0, 0)};
    dr::Figure f;
    f.add(std::vector<Point>{B[0], B[1], B[2]}, dr::Style().fill(pal::blue).fill_opacity(0.15).width(1.6));
    for (std::size_t i = 0; i < 3; ++i) f.segment(B[i], B[3], dr::Style().color(pal::red).dash({4, 3}));
    for (std::size_t i = 0; i < B.size(); ++i) f.add(B[i], dr::Style().label("p" + std::to_string(i)));
    f.add(t2::antipode(B[3]), dr::Style().label("~p3").color(pal::red));
    dr::PlaneView small;
    small.half_width = 3;
    // The sphere from above the triangle (which spans more than a hemisphere's worth of view),
    // tilted towards -y so that p3, straight below ~p3, shows below the edge p0 p1 rather than
    // hidden behind ~p3.
    dr::SphereView over;
    over.lat = 60;
    over.lon = -90;
    out.save(f, "no-hull", small, over);
    dr::Figure g;  // an antipodal pair: the segment between them is undefined
    const Point p = Point::cartesian(1, 0.5), q = t2::antipode(Point::cartesian(1, 0.5));
    g.add(p, dr::Style().label("p"));
    g.add(q, dr::Style().label("~p").label_angle(-60));
    const Point r = Point::cartesian(-1, 1);
    g.segment(r, p, dr::Style().color(pal::red).dash({4, 3}));  // both segments exist; together
    g.segment(r, q, dr::Style().color(pal::red).dash({4, 3}));  // they are half a great circle
    g.add(r, dr::Style().label("r"));
    out.save(g, "antipodal", small, sphere);
  }
  {  // The lower bound: points on the parabola y = x², all on the hull.
    std::vector<Point> P;
    for (double v : {-2.0, -1.5, -0.5, 0.0, 0.75, 1.25, 2.0}) P.push_back(Point::cartesian(v, v * v - 2));
    std::vector<Point> hull;
    for (std::size_t i : t2::convex_hull(P)) hull.push_back(P[i]);
    dr::Figure f;
    f.add(hull, hull_style);
    for (const Point& p : P) f.add(p);
    dr::PlaneView pv;
    pv.half_width = 3;
    out.save(f, "parabola", pv, dr::facing(P, sphere));
  }
  std::cerr << out.summary() << "\n";
}

}  // namespace

int main(int argc, char** argv) {
  const std::filesystem::path dir = dr::figures_dir(argc, argv, T2_FIGURES_DIR);
  every_algorithm();
  degenerate();
  no_hull();
  lower_bound();
  generated();
  figures(dir);
}
