// The figures of chapter 10 that main.cpp does not draw itself (see figures.hpp).
#include "figures.hpp"

#include <t2/gen/generate.hpp>
#include <t2/triangulation/delaunay.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <set>
#include <stdexcept>
#include <string>
#include <utility>

namespace chapter10 {

namespace dr = t2::draw;
namespace pal = t2::draw::palette;
using t2::Point;

namespace {

void check10(bool ok, const char* what) {
  if (!ok) throw std::logic_error(std::string("chapter 10 figures: check failed: ") + what);
}

using W3 = std::array<double, 3>;  // (w, x, y), the order of the library's exact vectors

W3 unit3(const Point& p) {
  const double n = std::sqrt(p.w() * p.w() + p.x() * p.x() + p.y() * p.y());
  return {p.w() / n, p.x() / n, p.y() / n};
}
W3 cross3(const W3& a, const W3& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
W3 normalized3(const W3& a) {
  const double n = std::sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]);
  return {a[0] / n, a[1] / n, a[2] / n};
}

// An edge of a triangulation as the pair of its indices, smaller first.
using Edge = std::pair<std::size_t, std::size_t>;
Edge edge_of(std::size_t a, std::size_t b) { return a < b ? Edge{a, b} : Edge{b, a}; }

// The edges of the finite triangles of tr, through `index` (the triangulation's vertex -> ours).
std::set<Edge> edges_of(const t2::Triangulation& tr, const std::vector<std::size_t>& index) {
  std::set<Edge> out;
  for (const auto& t : tr.finite_triangles())
    for (int k = 0; k < 3; ++k) out.insert(edge_of(index[t[k]], index[t[(k + 1) % 3]]));
  return out;
}

// The flip of section 2: the quadrilateral a b d c, its diagonal b c illegal because d is
// inside the circle of a b c, and the other diagonal a d.
void flip_figure(dr::FigurePairs& out) {
  const Point a = Point::cartesian(0.15, -0.8), b = Point::cartesian(1, 0), c = Point::cartesian(-1, 0),
              d = Point::cartesian(0.2, 0.55);
  check10(t2::orient(a, b, c) > 0 && t2::orient(c, b, d) > 0, "the triangles a b c and c b d turn left");
  check10(t2::in_circle(a, b, c, d) > 0, "d is inside the circle of a b c");
  check10(t2::in_circle(a, d, c, b) < 0, "after the flip, b is outside the circle of a d c");
  dr::Figure f;
  f.add(std::vector<Point>{a, b, d, c}, dr::Style().color(pal::blue).width(1.6).fill(pal::blue).fill_opacity(0.08));
  f.add(t2::circle_through(a, b, c), dr::Style().color(pal::grey).width(1.2));
  f.segment(b, c, dr::Style().color(pal::red).width(2).dash({5, 3}));
  f.segment(a, d, dr::Style().color(pal::green).width(2.2));
  f.add(a, dr::Style().label("a").label_angle(-90));
  f.add(b, dr::Style().label("b").label_angle(0));
  f.add(c, dr::Style().label("c").label_angle(180));
  f.add(d, dr::Style().label("d").label_angle(60));
  dr::PlaneView pv;
  pv.half_width = 1.4;
  out.save(f, "flip", pv, dr::facing({a, b, c, d}));
}

// Section 6: the merge of divide and conquer on sixteen points. The halves' triangulations, the
// cross edges the merge adds and the edges of the halves it deletes.
void merge_figure(dr::FigurePairs& out) {
  t2::gen::Options o;
  o.n = 16;
  o.seed = 9;
  std::vector<Point> P = t2::gen::points(t2::gen::Kind::uniform, o);
  for (Point& p : P) p = Point::cartesian(1.5 * p.x() / p.w(), 1.2 * p.y() / p.w());
  std::sort(P.begin(), P.end(), [](const Point& p, const Point& q) { return std::pair(p.x(), p.y()) < std::pair(q.x(), q.y()); });
  const std::size_t half = P.size() / 2;
  const std::vector<Point> L(P.begin(), P.begin() + static_cast<std::ptrdiff_t>(half)),
      R(P.begin() + static_cast<std::ptrdiff_t>(half), P.end());
  std::vector<std::size_t> all(P.size()), left(half), right(P.size() - half);
  for (std::size_t i = 0; i < P.size(); ++i) all[i] = i;
  for (std::size_t i = 0; i < half; ++i) left[i] = i;
  for (std::size_t i = half; i < P.size(); ++i) right[i - half] = i;
  const std::set<Edge> whole = edges_of(t2::delaunay(P), all);
  std::set<Edge> halves = edges_of(t2::delaunay(L), left);
  for (const Edge& e : edges_of(t2::delaunay(R), right)) halves.insert(e);
  std::map<Edge, int> faces;  // how many finite triangles of the whole have the edge
  for (const auto& t : t2::delaunay(P).finite_triangles())
    for (int k = 0; k < 3; ++k) ++faces[edge_of(t[k], t[(k + 1) % 3])];
  dr::Figure f;
  for (const Edge& e : halves) {
    const bool kept = whole.count(e) > 0;
    const char* colour = e.first < half ? pal::blue : pal::green;
    f.segment(P[e.first], P[e.second], kept ? dr::Style().color(colour).width(1.4)
                                            : dr::Style().color(pal::grey).width(1.2).dash({4, 3}));
  }
  int tangents = 0;
  for (const Edge& e : whole) {
    if ((e.first < half) == (e.second < half)) continue;
    const bool tangent = faces[e] == 1;  // on the hull of the whole: the lower or upper tangent
    tangents += tangent;
    f.segment(P[e.first], P[e.second], dr::Style().color(pal::orange).width(tangent ? 2.8 : 2).layer(1));
  }
  check10(tangents == 2, "two common tangents");
  for (const Point& p : P) f.add(p, dr::Style().size(3).layer(2));
  const double split = (P[half - 1].x() + P[half].x()) / 2;
  f.segment(Point::cartesian(split, -1.75), Point::cartesian(split, 1.75),
            dr::Style().color(pal::light_grey).width(1).dash({2, 3}).layer(-1));
  dr::PlaneView pv;
  pv.half_width = 1.7;
  out.save(f, "merge", pv, dr::facing(P));
}

// Section 1: a band face (a2, a1, b) of the two-sided Delaunay triangulation, the front hull edge
// a1 -> a2 and the back site b extreme beyond it, with its disk: the lune between the line
// a1 a2 (front) and its parallel through b (back), incircle.hpp's circle through them.
void band_figure(dr::FigurePairs& out) {
  const std::vector<Point> P = {Point::cartesian(-1.2, -0.6), Point::cartesian(0.9, -1.0), Point::cartesian(1.1, 0.7),
                                Point::cartesian(-0.3, 1.2),  Point::cartesian(0, 0),      Point(-1, 0.9, 0.3),
                                Point(-1, -0.5, 0.9),         Point(-1, -0.8, -0.7),       Point(-1, 0.4, -1.1)};
  const t2::Triangulation tr = t2::delaunay(P);
  // The band face with two front vertices whose front edge is P[1] -> P[2] (a1 -> a2 along the
  // front hull, counter-clockwise): the face (a2, a1, b).
  std::size_t a1 = 1, a2 = 2, b = P.size();
  for (const auto& t : tr.finite_triangles())
    for (int k = 0; k < 3; ++k)
      if (t[k] == a2 && t[(k + 1) % 3] == a1 && P[t[(k + 2) % 3]].w() < 0) b = t[(k + 2) % 3];
  check10(b < P.size(), "the band face on the hull edge p1 p2");
  for (std::size_t i = 0; i < P.size(); ++i)
    if (i != a1 && i != a2 && i != b) check10(t2::in_circle(P[a2], P[a1], P[b], P[i]) < 0, "the lune is empty");
  const Point E = Point(0, P[a1].x() - P[a2].x(), P[a1].y() - P[a2].y()), notE = t2::antipode(E);
  dr::Figure f;
  for (const auto& t : tr.finite_triangles())
    f.add(std::vector<Point>{P[t[0]], P[t[1]], P[t[2]]}, dr::Style().color(pal::light_grey).width(1));
  f.add(std::vector<Point>{notE, P[a2], P[a1], E, P[b]},
        dr::Style().color(pal::orange).width(1.8).fill(pal::orange).fill_opacity(0.18));
  f.add(std::vector<Point>{P[a2], P[a1], P[b]},
        dr::Style().color(pal::blue).width(2.4).layer(1));
  for (std::size_t i = 0; i < P.size(); ++i) f.add(P[i], dr::Style().size(3).layer(2));
  f.add(P[a1], dr::Style().size(3).label("a1").layer(2));
  f.add(P[a2], dr::Style().size(3).label("a2").layer(2));
  f.add(P[b], dr::Style().size(3).label("b").layer(2));
  f.add(E, dr::Style().size(3).label("E").label_angle(180).color(pal::orange).layer(2));
  f.add(notE, dr::Style().size(3).label("~E").label_angle(0).color(pal::orange).layer(2));
  dr::PlaneView pv;
  pv.half_width = 2;
  out.save(f, "band", pv, dr::facing({P[a1], P[a2], P[b]}));
}

}  // namespace

std::vector<Point> add_antipodal_lunes(dr::Figure& f, const t2::Triangulation& tr, const std::vector<Point>& P) {
  std::vector<Point> middles;
  for (const t2::AntipodalEdge& e : tr.antipodal_edges()) {
    // The inward normals of the hull edges u -> z and z -> w at z; the edge leaves z along
    // minus their sum (antipodal_edge.hpp), a unit tangent t: the half circle z, t, ¬z.
    const W3 z = unit3(P[e.z]);
    const W3 n1 = normalized3(cross3(unit3(P[e.u]), z)), n2 = normalized3(cross3(z, unit3(P[e.w])));
    const W3 t = normalized3({-(n1[0] + n2[0]), -(n1[1] + n2[1]), -(n1[2] + n2[2])});
    std::vector<Point> arc;
    for (int k = 0; k <= 12; ++k) {
      const double a = k * std::acos(-1.0) / 12, c = std::cos(a), s = std::sin(a);
      arc.push_back(Point(c * z[0] + s * t[0], c * z[1] + s * t[1], c * z[2] + s * t[2]));
    }
    arc.front() = P[e.z];
    arc.back() = P[e.nz];
    // A quarter of the way from the front end: that end and the edge's middle both in view.
    middles.push_back(P[e.z].w() > 0 ? arc[3] : arc[9]);
    for (const std::uint32_t third : {e.w, e.u}) {  // the lunes (w, z, ¬z) and (z, u, ¬z)
      std::vector<Point> lune = arc;
      lune.push_back(P[third]);
      f.add(lune, dr::Style().color(pal::orange).width(0).fill(pal::orange).fill_opacity(third == e.w ? 0.25 : 0.12));
    }
    f.polyline(arc, dr::Style().color(pal::red).width(2.6).layer(1));
  }
  return middles;
}

void more_figures(dr::FigurePairs& out) {
  flip_figure(out);
  merge_figure(out);
  band_figure(out);
}

}  // namespace chapter10
