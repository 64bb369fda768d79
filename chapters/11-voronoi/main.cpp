// Chapter 11: the Voronoi diagram of T² as the dual of the Delaunay complex. Prints the listings
// that `t2 voronoi` prints for the chapter's small inputs, checks the antipodal theorem against
// a brute-force farthest-point diagram, counts vertices on larger inputs, shows the one formula
// for circumcentres, and draws seed 000's figures 5.22-5.24 and a cocircular case in both models.
#include <t2/t2.hpp>
#include <t2/gen/generate.hpp>
#include <t2/kernel/distance.hpp>
#include <t2/voronoi/complex.hpp>
#include <t2/voronoi/voronoi.hpp>

#include <algorithm>
#include <filesystem>
#include <iostream>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

namespace {

namespace dr = t2::draw;
namespace pal = t2::draw::palette;
using t2::ExactPoint;
using t2::Integer;
using t2::Point;
using Index = t2::VoronoiDiagram::Index;

void require(bool ok, const char* what) {
  if (!ok) throw std::logic_error(std::string("chapter 11: check failed: ") + what);
}

// The sites of the chapter's examples (the files of data/examples/voronoi-*.t2).
const std::vector<Point> kSix = {Point::cartesian(0, 0), Point::cartesian(4, 0), Point::cartesian(5, 3),
                                 Point::cartesian(2, 5), Point::cartesian(-1, 2), Point::cartesian(2, 2)};
const std::vector<Point> kSquare = {Point::cartesian(2, 0), Point::cartesian(0, 2), Point::cartesian(-2, 0),
                                    Point::cartesian(0, -2), Point::cartesian(4, 3)};
const std::vector<Point> kLine = {Point::cartesian(0, 0), Point::cartesian(1, 1), Point::cartesian(3, 3)};
// Front sites and back sites (a back point [-1, -x, -y] is drawn at (x, y)).
const std::vector<Point> kTwo = {Point::cartesian(0, 0), Point::cartesian(3, 0),  Point::cartesian(1, 3),
                                 Point(-1, -1, -1),      Point(-1, -4, -2),        Point(-1, 0, -4)};

ExactPoint reduced(const ExactPoint& v) {  // divided by the gcd of its coordinates, as t2 voronoi
  Integer g = gcd(gcd(v.w(), v.x()), v.y());
  if (g == 0) return v;
  return ExactPoint(Integer(v.w() / g), Integer(v.x() / g), Integer(v.y() / g));
}

std::string coords(const ExactPoint& v) {
  const ExactPoint r = reduced(v);
  return r.w().get_str() + " " + r.x().get_str() + " " + r.y().get_str();
}

// The output of `t2 voronoi` (tools/t2/cmd_voronoi.cpp) for the diagram vd.
void print_listing(const t2::VoronoiDiagram& vd) {
  for (Index v = 0; v < vd.size(); ++v) {
    std::cout << "vertex " << coords(vd.vertex(v)) << " ";
    for (Index s : vd.vertex_sites(v)) std::cout << " " << s;
    std::cout << "\n";
  }
  for (const auto& e : vd.edges) std::cout << "edge " << e.a << " " << e.b << "  " << e.s << " " << e.t << "\n";
  for (auto [s, t] : vd.lines) std::cout << "line " << s << " " << t << "\n";
}

int side(const ExactPoint& v) { return sgn(v.w()); }

// Vertices in front, on Ω and behind.
std::string sides(const t2::VoronoiDiagram& vd) {
  int f = 0, o = 0, b = 0;
  for (Index v = 0; v < vd.size(); ++v) {
    const int s = side(vd.vertex(v));
    (s > 0 ? f : s < 0 ? b : o) += 1;
  }
  return std::to_string(f) + " in front, " + std::to_string(o) + " on Omega, " + std::to_string(b) + " behind";
}

void examples() {
  std::cout << "== six front sites (data/examples/voronoi-6.t2)\n";
  const t2::VoronoiDiagram vd = t2::voronoi(kSix);
  print_listing(vd);
  std::cout << "vertices: " << vd.size() << " (" << sides(vd) << "), edges: " << vd.edges.size() << "\n";
  //> farthest-check
  // The antipodal theorem, against brute force in rationals: the farthest-point Voronoi
  // vertices are the centres of the circles through three sites that hold every site.
  using Q = t2::Rational;
  std::set<std::pair<Q, Q>> brute, back;
  std::vector<std::pair<Q, Q>> S;
  for (const Point& p : kSix)
    S.emplace_back(t2::to_rational(p.x()), t2::to_rational(p.y()));
  auto d2 = [](const std::pair<Q, Q>& u, const std::pair<Q, Q>& v) {
    const Q dx = u.first - v.first, dy = u.second - v.second;
    return Q(dx * dx + dy * dy);
  };
  for (std::size_t i = 0; i < S.size(); ++i)
    for (std::size_t j = i + 1; j < S.size(); ++j)
      for (std::size_t k = j + 1; k < S.size(); ++k) {
        const auto& [ax, ay] = S[i];
        const auto& [bx, by] = S[j];
        const auto& [cx, cy] = S[k];
        const Q det = 2 * (ax * (by - cy) + bx * (cy - ay) + cx * (ay - by));
        if (det == 0) continue;  // collinear
        const Q a2 = ax * ax + ay * ay, b2 = bx * bx + by * by, c2 = cx * cx + cy * cy;
        const std::pair<Q, Q> z((a2 * (by - cy) + b2 * (cy - ay) + c2 * (ay - by)) / det,
                                (a2 * (cx - bx) + b2 * (ax - cx) + c2 * (bx - ax)) / det);
        bool holds_all = true;
        for (const auto& d : S) holds_all = holds_all && d2(d, z) <= d2(S[i], z);
        if (holds_all) brute.insert(z);
      }
  for (Index v = 0; v < vd.size(); ++v) {
    const ExactPoint x = vd.vertex(v);
    if (side(x) < 0) back.emplace(Q(x.x()) / x.w(), Q(x.y()) / x.w());  // its drawn spot
  }
  std::cout << "farthest-point vertices by brute force: " << brute.size()
            << "; back Voronoi vertices: " << back.size() << "; drawn at the same spots: "
            << (brute == back ? "yes" : "NO") << "\n";
  //< farthest-check
  require(brute == back, "the back half is the farthest-point diagram");
  std::cout << "\n";

  std::cout << "== one formula for every face\n";
  //> one-formula
  const Point &a = kSix[0], &b = kSix[1], &c = kSix[3];
  std::cout << "circumcentre(p0, p1, p3) = [" << coords(t2::circumcentre(a, b, c)) << "]\n";
  std::cout << "circumcentre(p0, p3, p1) = [" << coords(t2::circumcentre(a, c, b)) << "]\n";
  const Point na = t2::antipode(a), nb = t2::antipode(b), nc = t2::antipode(c);
  std::cout << "circumcentre(~p0, ~p3, ~p1) = [" << coords(t2::circumcentre(na, nc, nb))
            << "]\n";
  //< one-formula
  std::cout << "\n";

  std::cout << "== cocircular sites (data/examples/voronoi-square.t2)\n";
  const t2::VoronoiDiagram sq = t2::voronoi(kSquare);
  print_listing(sq);
  std::cout << "\n";

  std::cout << "== collinear sites (data/examples/voronoi-line.t2)\n";
  print_listing(t2::voronoi(kLine));
  std::cout << "\n";

  std::cout << "== front and back sites (data/examples/voronoi-two.t2)\n";
  const t2::VoronoiDiagram two = t2::voronoi(kTwo);
  print_listing(two);
  std::cout << "vertices: " << two.size() << " (" << sides(two) << ")\n\n";
}

void counts() {
  std::cout << "== how many vertices\n";
  //> counts
  t2::gen::Options o;
  o.seed = 11;
  for (std::size_t n : {1000, 100000}) {
    o.n = n;
    const std::vector<Point> P = t2::gen::points(t2::gen::Kind::uniform, o);
    const t2::DelaunayComplex dc = t2::delaunay_complex(P);
    std::size_t h = 0;  // the hull corners: the sites with a back cell
    std::vector<char> back(P.size(), 0);
    for (std::size_t f = 0; f < dc.faces.size(); ++f)
      if (dc.turns[f] == t2::NEGATIVE)
        for (Index s : dc.faces[f]) h += !back[s], back[s] = 1;
    const t2::VoronoiDiagram vd = t2::voronoi(dc);
    const auto behind = std::count(dc.turns.begin(), dc.turns.end(), t2::NEGATIVE);
    std::cout << "n = " << n << ", h = " << h << ": " << vd.size() << " vertices, "
              << vd.size() - behind << " in front, " << behind << " behind; "
              << vd.edges.size() << " edges\n";
    require(vd.size() == 2 * n - 4 && std::size_t(behind) == h - 2,
            "2n - 4 vertices, h - 2 behind");
    require(vd.edges.size() == 3 * n - 6, "3n - 6 edges");
  }
  //< counts
  o.n = 1000;
  o.back = 0.3;
  const t2::VoronoiDiagram vd = t2::voronoi(t2::gen::points(t2::gen::Kind::both_sides, o));
  std::cout << "both-sides n = 1000: " << vd.size() << " vertices (" << sides(vd) << ")\n\n";
}

// --- figures ----------------------------------------------------------------------------------

ExactPoint plus(const ExactPoint& a, const ExactPoint& b) {
  return ExactPoint(Integer(a.w() + b.w()), Integer(a.x() + b.x()), Integer(a.y() + b.y()));
}
ExactPoint cross(const ExactPoint& a, const ExactPoint& b) {  // as vectors (w, x, y)
  return ExactPoint(Integer(a.x() * b.y() - a.y() * b.x()), Integer(a.y() * b.w() - a.w() * b.y()),
                    Integer(a.w() * b.x() - a.x() * b.w()));
}

// A point strictly inside the arc of the edge e: on the bisector of its sites, between its
// vertices, where no site is nearer than e.s (exact; the other arc of the great circle fails).
ExactPoint inside_edge(const t2::VoronoiDiagram& vd, const t2::VoronoiDiagram::Edge& e) {
  const ExactPoint a = vd.vertex(e.a), b = vd.vertex(e.b), s = t2::to_exact(vd.sites[e.s]);
  ExactPoint m = plus(a, b);
  if (a == t2::antipode(b)) {  // either half of the bisector's great circle: 90° from a
    const ExactPoint t = t2::to_exact(vd.sites[e.t]);
    const bool same = sgn(s.w()) == sgn(t.w()) && sgn(s.w()) != 0;
    const ExactPoint n = same ? cross(a, t2::mix(Integer(abs(t.w())), s, Integer(abs(s.w())), t))
                              : ExactPoint(Integer(1), Integer(0), Integer(0));  // Ω
    m = cross(n, a);
  }
  for (const Point& d : vd.sites) {
    try {
      if (t2::compare_distance(t2::to_exact(d), s, m) == t2::NEGATIVE) return t2::antipode(m);
    } catch (const t2::Undefined&) {  // m on Ω between a front and a back site: no order
    }
  }
  return m;
}

// The arc p → q (not antipodes), split where it crosses Ω, each part styled by its side.
void arc(dr::Figure& f, const Point& p, const Point& q, const dr::Style& front, const dr::Style& back) {
  auto st = [&](const Point& u, const Point& v) { return u.w() > 0 || v.w() > 0 ? front : back; };
  if (p.w() * q.w() < 0) {
    const Point c = t2::normalized(t2::mix(std::abs(q.w()), p, std::abs(p.w()), q));
    f.segment(p, c, st(p, p));
    f.segment(c, q, st(q, q));
    return;
  }
  f.segment(p, q, st(p, q));
}

// The Voronoi edges and vertices of vd: front parts in `front`, back parts in `back`.
void draw_diagram(dr::Figure& f, const t2::VoronoiDiagram& vd, const dr::Style& front, const dr::Style& back) {
  for (const auto& e : vd.edges) {
    const Point a = t2::normalized(t2::to_double(vd.vertex(e.a)));
    const Point b = t2::normalized(t2::to_double(vd.vertex(e.b)));
    const Point m = t2::normalized(t2::to_double(inside_edge(vd, e)));
    arc(f, a, m, front, back);
    arc(f, m, b, front, back);
  }
  for (Index v = 0; v < vd.size(); ++v) {
    const Point x = t2::normalized(t2::to_double(vd.vertex(v)));
    f.add(x, dr::Style().color(x.w() > 0 ? front.color() : back.color()).size(2.5).layer(2));
  }
}

void label_sites(dr::Figure& f, const std::vector<Point>& P) {
  for (std::size_t k = 0; k < P.size(); ++k) f.add(P[k], dr::Style().label("p" + std::to_string(k)).layer(3));
}

// The sites moved by X -> (X - c) / s on their own side: the diagram moves with them (distances
// scale by 1/s on each side, across the sides too), and the sphere shows them near its pole.
std::vector<Point> fit(const std::vector<Point>& P, double cx, double cy, double s) {
  std::vector<Point> out;
  for (const Point& p : P) {
    const double e = p.w() > 0 ? 1 : -1;
    out.emplace_back(e, e * (p.x() / p.w() - cx) / s, e * (p.y() / p.w() - cy) / s);
  }
  return out;
}

void figures(const std::filesystem::path& dir) {
  dr::FigurePairs out(dir);
  const dr::Style red = dr::Style().color(pal::red).width(1.8);
  const dr::Style faint = dr::Style().color(pal::light_grey).width(1.2);
  dr::SphereView above;
  above.lat = 50;
  above.lon = -70;
  dr::SphereView below = above;
  below.lat = -65;
  below.lon = 110;  // facing the back vertices of figure 5.24
  // The diagram of P in red over the items of f, its sites labelled, in both models.
  auto plain = [&](const std::vector<Point>& P, dr::Figure f, const std::string& name, double half_width,
                   const dr::SphereView& sv) {
    draw_diagram(f, t2::voronoi(P), red, red);
    label_sites(f, P);
    dr::PlaneView pv;
    pv.half_width = half_width;
    out.save(f, name, pv, sv);
  };
  // Figure 5.23: front sites; the diagram reaches across Ω into the back.
  plain(fit(kSix, 2, 2.5, 4), dr::Figure(), "front", 1.5, above);
  {  // Figure 5.24: the same diagram, its back half highlighted: the farthest-point diagram.
    // Less shrunk, so that the back half, near the middle of the sites, shows on the sphere.
    const std::vector<Point> Q = fit(kSix, 2, 2.5, 2);
    dr::Figure g;
    draw_diagram(g, t2::voronoi(Q), faint, red);
    const t2::DelaunayComplex dc = t2::delaunay_complex(Q);
    for (std::size_t k = 0; k < dc.faces.size(); ++k)
      if (dc.turns[k] == t2::NEGATIVE) {
        const auto& t = dc.faces[k];
        g.add(std::vector<Point>{Q[t[0]], Q[t[1]], Q[t[2]]}, dr::Style().color(pal::blue).width(1));
      }
    label_sites(g, Q);
    dr::PlaneView pv;
    pv.half_width = 3;
    out.save(g, "farthest", pv, below);
  }
  // Figure 5.22: sites on both sides.
  dr::SphereView side = above;
  side.lat = 25;
  plain(fit(kTwo, 1.5, 1.5, 3), dr::Figure(), "two-sides", 2, side);
  {  // Four cocircular sites and one more: one front vertex where four cells meet.
    const std::vector<Point> P = fit(kSquare, 0.5, 0.5, 3);
    dr::Figure f;
    f.add(t2::circle_through(P[0], P[1], P[2]), dr::Style().color(pal::light_grey).dash({3, 3}));
    plain(P, f, "cocircular", 1.6, above);
  }
  std::cerr << out.summary() << "\n";
}

}  // namespace

int main(int argc, char** argv) {
  const std::filesystem::path dir = dr::figures_dir(argc, argv, T2_FIGURES_DIR);
  examples();
  counts();
  figures(dir);
}
