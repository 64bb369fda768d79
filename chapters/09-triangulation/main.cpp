// Chapter 09: triangulations. The counts of Euler's formula, the operations of the flat
// structure (insertion in a face, on an edge, outside the hull, the flip), the sweep of
// t2/triangulation/triangulate.hpp, and the remembering walk on a Delaunay triangulation and on
// the sweep's; the figures of the chapter in both models (seed 000, figures 5.12-5.20 redrawn).
#include <t2/t2.hpp>
#include <t2/gen/generate.hpp>
#include <t2/triangulation/antipodal_edge.hpp>
#include <t2/triangulation/delaunay.hpp>
#include <t2/triangulation/triangulate.hpp>
#include <t2/triangulation/triangulate_t2.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <iostream>
#include <stdexcept>
#include <string>
#include <vector>

namespace {

namespace dr = t2::draw;
namespace pal = t2::draw::palette;
using t2::Point;
using t2::Triangulation;
using Index = Triangulation::Index;

void require(bool ok, const char* what) {
  if (!ok) throw std::logic_error(std::string("chapter 09: check failed: ") + what);
}

// Ten front points, no three collinear, no four cocircular.
std::vector<Point> small_set() {
  //> small-set
  return {Point::cartesian(0, 0),    Point::cartesian(4, -1), Point::cartesian(7, 1),
          Point::cartesian(2, 3),    Point::cartesian(5, 4),  Point::cartesian(8, 5),
          Point::cartesian(1, 6),    Point::cartesian(4, 8),  Point::cartesian(6.5, 7.5),
          Point::cartesian(3.5, 1.5)};
  //< small-set
}

std::string triangles(const Triangulation& tr) {
  auto t = tr.finite_triangles();
  std::sort(t.begin(), t.end());
  std::string s;
  for (const auto& x : t) s += " (" + std::to_string(x[0]) + " " + std::to_string(x[1]) + " " + std::to_string(x[2]) + ")";
  return s;
}

void counts() {
  std::cout << "== a triangulation of ten points (the sweep)\n";
  //> counts
  const std::vector<Point> P = small_set();
  const Triangulation tr = t2::triangulate(P);
  const std::size_t n = P.size(), h = tr.hull_edges().size(),
                    t = tr.finite_triangles().size();
  std::cout << "n = " << n << " points, h = " << h << " on the hull\n";
  std::cout << "triangles: " << t << " = 2n - h - 2 = " << 2 * n - h - 2 << "\n";
  std::cout << "with v-infinity: " << tr.size()
            << " triangles = 2(n + 1) - 4 = " << 2 * (n + 1) - 4 << "\n";
  std::cout << "triangles:" << triangles(tr) << "\n";
  //< counts
  require(t == 2 * n - h - 2 && tr.size() == 2 * (n + 1) - 4 && tr.valid(), "Euler");
  std::cout << "\n";
}

void operations() {
  std::cout << "== the operations, one after the other\n";
  //> operations
  const std::vector<Point> P = {Point::cartesian(0, 0), Point::cartesian(4, 0),
                                Point::cartesian(2, 4), Point::cartesian(2, 1),
                                Point::cartesian(3, 2), Point::cartesian(5, 3)};
  Triangulation tr(P);
  tr.make_triangle(0, 1, 2);  // t0 = (0 1 2) and three infinite triangles
  std::cout << "make_triangle:" << triangles(tr) << "\n";
  tr.insert_in_face(0, 3);  // p3 = (2, 1) lies inside t0
  std::cout << "insert_in_face p3:" << triangles(tr) << "\n";
  // (3 1 2): its edge opposite p3 (slot 0) is the segment p1 p2, which holds p4
  const Index t = 4;
  tr.insert_on_edge(t, 0, 4);
  std::cout << "insert_on_edge p4:" << triangles(tr) << "\n";
  // p5 = (5, 3) is outside the hull, beyond the edge p1 p4: insert it in that infinite
  // triangle.
  Index f = 0;
  while (tr.slot(f, Triangulation::infinite) < 0 ||
         !t2::detail::sees_hull_edge(tr, f, P[5]))
    ++f;
  tr.insert_in_face(f, 5);
  std::cout << "p5 into the infinite triangle " << f << ":" << triangles(tr) << "\n";
  const Index n = static_cast<Index>(tr.size());
  // the new infinite triangles: remove the reflex angles at p5
  for (Index g : {f, n - 2, n - 1})
    if (tr.vertex(g, 1) == Triangulation::infinite ||
        tr.vertex(g, 2) == Triangulation::infinite)
      t2::detail::flip_hull_chain(tr, g);
  std::cout << "after step 35:" << triangles(tr) << "\n";
  std::cout << "valid: " << (tr.valid() ? "yes" : "no")
            << ", hull edges: " << tr.hull_edges().size() << "\n";
  //< operations
  require(tr.valid(), "operations");
  std::cout << "\n";
}

// The walk, counting its orientation tests, from triangle 0 to every query point.
double walk_cost(const Triangulation& tr, const std::vector<Point>& queries) {
  std::uint64_t tests = 0;
  std::uint32_t rng = 12345;
  for (const Point& q : queries) {
    const auto loc = tr.locate(q, 0, [&](const Point& a, const Point& b, const Point& c) {
      ++tests;
      return t2::orient(a, b, c);
    }, rng);
    require(loc.t != Triangulation::none, "located");
  }
  return double(tests) / double(queries.size());
}

void walks() {
  std::cout << "== the remembering walk: orientation tests per query, 1000 queries\n";
  //> walks
  t2::gen::Options o;
  o.seed = 9;
  for (std::size_t n : {1000, 10000, 100000}) {
    o.n = n;
    const std::vector<Point> P = t2::gen::points(t2::gen::Kind::uniform, o);
    o.n = 1000;
    const std::vector<Point> Q = t2::gen::points(t2::gen::Kind::uniform, o);
    std::cout << "n = " << n << ": Delaunay " << int(walk_cost(t2::delaunay(P), Q))
              << ", sweep " << int(walk_cost(t2::triangulate(P), Q)) << "\n";
  }
  //< walks
  std::cout << "\n";
}

// Seed 000, figures 5.18-5.20 redrawn from t2::triangulate_t2: the hull triangle z w u, the
// antipode of z (5.18, the two lunes at the antipodal edge along the bisector), then t inside the
// old hull edge z -> w (5.19, a flat face), or s on the antipodal edge (5.20, the lunes gone).
// Lunes are drawn through the midpoint of their antipodal edge (a double, for the picture only:
// the library decides sides exactly, t2/triangulation/antipodal_edge.hpp); flat faces as thick
// orange segments; the lune at w green, the one at u purple, their common edge red.
void antipodal_figures(const std::filesystem::path& dir, int& written, int& count) {
  dr::PlaneView plane;
  plane.half_width = 5;
  dr::SphereView sphere;
  sphere.lat = 30;  // from behind the antipodal edge: both lunes and the hull in sight
  sphere.lon = -135;
  // z at the centre of the front side, where the spherical bisector is the planar one: the
  // unit vectors to w and u are (1, 0) and (0.6, 0.8), the edge z -> ¬z leaves along (-2, -1).
  const Point z = Point::cartesian(0, 0), w = Point::cartesian(2, 0), u = Point::cartesian(3, 4);
  // The midpoint of the half great circle z -> ¬z along the outward bisector: -(n1 + n2) with
  // n1, n2 the unit poles of the hull edges u -> z and z -> w (antipodal_edge.hpp).
  auto bisector_midpoint = [](const Point& z, const Point& u, const Point& w) {
    auto v = [](const Point& p) { return std::array<double, 3>{p.w(), p.x(), p.y()}; };
    auto cross = [](std::array<double, 3> a, std::array<double, 3> b) {
      std::array<double, 3> c{a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
      const double n = std::sqrt(c[0] * c[0] + c[1] * c[1] + c[2] * c[2]);
      return std::array<double, 3>{c[0] / n, c[1] / n, c[2] / n};
    };
    const auto n1 = cross(v(u), v(z)), n2 = cross(v(z), v(w));
    return Point(-(n1[0] + n2[0]), -(n1[1] + n2[1]), -(n1[2] + n2[2]));
  };
  auto draw = [&](const std::vector<Point>& P, const std::string& name) {
    const t2::TriangulationT2 r = t2::triangulate_t2(P, t2::InsertionOrder::input);  // the seed's order
    const Triangulation& tr = r.tr;
    dr::Figure f;
    const dr::Style proper = dr::Style().color(pal::blue).fill(pal::blue).fill_opacity(0.1);
    for (Index t = 0; t < tr.size(); ++t) {
      const Index a = tr.vertex(t, 0), b = tr.vertex(t, 1), c = tr.vertex(t, 2);
      switch (t2::face_kind(tr, t)) {
        case t2::FaceKind::infinite: break;  // none here: the antipode destroys the hull
        case t2::FaceKind::front:
        case t2::FaceKind::back:
        case t2::FaceKind::band:
        case t2::FaceKind::omega: f.add(std::vector<Point>{P[a], P[b], P[c]}, proper); break;
        case t2::FaceKind::flat:
          for (auto [x, y] : {std::pair{a, b}, {b, c}, {c, a}}) f.segment(P[x], P[y], dr::Style().color(pal::orange).width(3));
          break;
        case t2::FaceKind::lune: {
          // rotate so that (x, y) is the antipodal pair, k the third vertex
          Index x = a, y = b, k = c;
          if (P[b] == t2::antipode(P[c])) x = b, y = c, k = a;
          if (P[c] == t2::antipode(P[a])) x = c, y = a, k = b;
          const t2::AntipodalEdge& e = tr.antipodal_edges().front();
          const Point m = bisector_midpoint(P[e.z], P[e.u], P[e.w]);
          const bool at_w = t2::side_of_antipodal_edge(P, e, P[k]) > 0;  // green, else purple
          f.add(std::vector<Point>{P[x], m, P[y], P[k]},  // x -> m -> y: the half circle
                dr::Style().color(pal::blue).fill(at_w ? pal::green : pal::purple).fill_opacity(0.3));
          f.polyline(std::vector<Point>{P[x], m, P[y]}, dr::Style().color(pal::red).width(2.5));
          break;
        }
      }
    }
    const std::string names[] = {"z", "w", "u", "¬z", name == "flat-face" ? "t" : "s"};
    for (std::size_t k = 0; k < P.size(); ++k) f.add(P[k], dr::Style().label(names[k]));
    written += dr::save(f, plane, dir / (name + "-plane.svg"));
    written += dr::save(f, sphere, dir / (name + "-sphere.svg"));
    count += 2;
  };
  draw({z, w, u, t2::antipode(z)}, "antipode");
  draw({z, w, u, t2::antipode(z), Point::cartesian(1, 0)}, "flat-face");
  draw({z, w, u, t2::antipode(z), Point(0, -2, -1)}, "lunes-gone");  // s: the edge's midpoint, on Ω
}

void figures(const std::filesystem::path& dir) {
  int written = 0, count = 0;
  dr::PlaneView plane;
  plane.half_width = 5;
  dr::SphereView sphere;
  sphere.lat = 40;
  sphere.lon = -20;
  // The points are drawn scaled and shifted so that the set sits around the centre of the views.
  auto shifted = [](const std::vector<Point>& P) {
    std::vector<Point> out;
    for (const Point& p : P) out.push_back(Point::cartesian(p.x() / p.w() / 2 - 2.5, p.y() / p.w() / 2 - 2));
    return out;
  };
  // The finite triangles (those at a marked vertex in orange), extra segments, labelled points.
  auto draw = [&](const Triangulation& tr, const std::vector<Point>& P, Index marked,
                  const std::vector<std::pair<Index, Index>>& extra, const std::string& name) {
    dr::Figure f;
    const auto S = shifted(P);
    for (const auto& t : tr.finite_triangles()) {
      const bool hot = t[0] == marked || t[1] == marked || t[2] == marked;
      f.add(std::vector<Point>{S[t[0]], S[t[1]], S[t[2]]},
            dr::Style().color(pal::blue).fill(hot ? pal::orange : pal::blue).fill_opacity(hot ? 0.35 : 0.1));
    }
    for (auto [a, b] : extra) f.segment(S[a], S[b], dr::Style().color(pal::orange).width(1.6));
    double cx = 0, cy = 0;  // labels point away from the centre of the set
    for (const Point& p : S) cx += p.x() / double(S.size()), cy += p.y() / double(S.size());
    for (std::size_t k = 0; k < S.size(); ++k)
      f.add(S[k], dr::Style().label("p" + std::to_string(k))
                      .label_angle(std::atan2(S[k].y() - cy, S[k].x() - cx) * 180 / 3.141592653589793));
    written += dr::save(f, plane, dir / (name + "-plane.svg"));
    written += dr::save(f, sphere, dir / (name + "-sphere.svg"));
    count += 2;
  };
  const std::vector<Point> P = small_set();
  draw(t2::triangulate(P), P, Triangulation::none, {}, "sweep");
  // Seed 000, figures 5.16 and 5.17: p9 outside the hull of the others. Inserted in the infinite
  // triangle of one hull edge it sees, it gets two edges (5.16); the flips of Algorithm 9 then
  // join it to every hull vertex it sees (5.17).
  std::vector<Point> Q(P.begin(), P.end() - 1);
  Q.push_back(Point::cartesian(10.5, 2.5));
  const Triangulation base = t2::triangulate(std::vector<Point>(Q.begin(), Q.end() - 1));
  std::vector<std::pair<Index, Index>> first_edges;
  for (auto [a, b] : base.hull_edges())
    if (first_edges.empty() && t2::orient(Q[a], Q[b], Q[9]) < 0) first_edges = {{a, 9}, {b, 9}};
  draw(base, Q, Triangulation::none, first_edges, "outside-before");
  draw(t2::triangulate(Q), Q, 9, {}, "outside-after");
  antipodal_figures(dir, written, count);
  std::cerr << "figures: " << count << " in " << dir.string() << " (" << written << " changed)\n";
}

}  // namespace

int main(int argc, char** argv) {
  const std::filesystem::path dir = dr::figures_dir(argc, argv, T2_FIGURES_DIR);
  counts();
  operations();
  walks();
  figures(dir);
}
