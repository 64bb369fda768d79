// The labelled 3-D figures of chapter 08 (see figures.hpp).
#include "figures.hpp"

#include <t2/draw/polyhedron.hpp>
#include <t2/gen/generate.hpp>
#include <t2/hull3d.hpp>

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>
#include <stdexcept>
#include <string>
#include <utility>

namespace chapter08 {

namespace dr = t2::draw;
namespace pal = t2::draw::palette;
using t2::Point;
using t2::Point3;
using t2::Triangle3;

namespace {

void check08(bool ok, const char* what) {
  if (!ok) throw std::logic_error(std::string("chapter 08 figures: check failed: ") + what);
}

Point3 minus(const Point3& a, const Point3& b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
Point3 cross(const Point3& a, const Point3& b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
double dot(const Point3& a, const Point3& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }

// Parallel projection along the view direction of a View3 (as t2::draw::save_polyhedron sees),
// centred on `centre`: a point of space becomes the front point of the plane where it is drawn.
struct Camera {
  Point3 eye, right, up, centre;
  Camera(const dr::View3& v, const Point3& c) : centre(c) {
    const double az = v.azimuth * std::numbers::pi / 180, el = v.elevation * std::numbers::pi / 180;
    eye = {std::cos(el) * std::cos(az), std::cos(el) * std::sin(az), std::sin(el)};
    right = {-std::sin(az), std::cos(az), 0};
    up = cross(eye, right);
  }
  Point at(const Point3& p) const {
    const Point3 w = minus(p, centre);
    return Point::cartesian(dot(w, right), dot(w, up));
  }
  // True when the outward triangle a b c faces the viewer.
  bool sees(const Point3& a, const Point3& b, const Point3& c) const {
    return dot(cross(minus(b, a), minus(c, a)), eye) > 0;
  }
  // The plane view that holds every point of P with a margin.
  dr::PlaneView plane(const std::vector<Point3>& P, double margin = 1.12) const {
    double r = 0;
    for (const Point3& p : P) {
      const Point q = at(p);
      r = std::max(r, std::hypot(q.x(), q.y()));
    }
    dr::PlaneView v;
    v.half_width = margin * r;
    v.omega = false;
    return v;
  }
};

Point3 middle(const std::vector<Point3>& P) {
  Point3 lo = P[0], hi = P[0];
  for (const Point3& p : P) {
    lo = {std::min(lo.x, p.x), std::min(lo.y, p.y), std::min(lo.z, p.z)};
    hi = {std::max(hi.x, p.x), std::max(hi.y, p.y), std::max(hi.z, p.z)};
  }
  return {(lo.x + hi.x) / 2, (lo.y + hi.y) / 2, (lo.z + hi.z) / 2};
}

// The hull triangles T of P: the faces that face the viewer filled with `fill(k)` (a colour, k
// the index of the triangle in T),
// the edges between two faces turned away dashed grey, the others solid.
template <class Fill>
void draw_hull(dr::Figure& f, const std::vector<Point3>& P, const std::vector<Triangle3>& T, const Camera& cam,
               Fill fill) {
  std::map<std::pair<std::uint32_t, std::uint32_t>, bool> seen;  // edge -> seen from a visible face
  for (std::size_t k = 0; k < T.size(); ++k) {
    const Triangle3& t = T[k];
    const bool vis = cam.sees(P[t[0]], P[t[1]], P[t[2]]);
    for (int k = 0; k < 3; ++k) {
      const auto e = std::minmax(t[k], t[(k + 1) % 3]);
      seen[{e.first, e.second}] = seen[{e.first, e.second}] || vis;
    }
    if (vis)
      f.add(std::vector<Point>{cam.at(P[t[0]]), cam.at(P[t[1]]), cam.at(P[t[2]])},
            dr::Style().width(0).color(pal::white).fill(fill(k)).fill_opacity(0.35));
  }
  for (const auto& [e, vis] : seen)
    f.segment(cam.at(P[e.first]), cam.at(P[e.second]),
              vis ? dr::Style().color(pal::black).width(1.4).layer(1)
                  : dr::Style().color(pal::grey).width(1).dash({4, 3}));
}

dr::View3 view_from(const Point3& d, double turn, double tilt) {
  const double n = std::sqrt(dot(d, d));
  dr::View3 v;
  v.azimuth = std::atan2(d.y, d.x) * 180 / std::numbers::pi + turn;
  v.elevation = std::asin(d.z / n) * 180 / std::numbers::pi + tilt;
  return v;
}

std::vector<Point3> cube_points(std::size_t n, std::uint64_t seed) {
  t2::gen::Options o;
  o.n = n;
  o.seed = seed;
  std::vector<Point3> P;
  for (const auto& [x, y, z] : t2::gen::points3(t2::gen::Kind::cube, o)) P.push_back({x, y, z});
  return P;
}

}  // namespace

void lifted_figure(const std::vector<Point>& A, const std::filesystem::path& dir) {
  std::vector<Point3> L, B;  // the lifted points (z / 8) and the points in the plane z = -0.6
  for (const Point& p : A) {
    const Point3 q = t2::lift(p);
    L.push_back({q.x, q.y, q.z / 8});
    B.push_back({q.x, q.y, -0.6});
  }
  dr::View3 v;
  v.elevation = -20;  // from below: the lower hull faces the viewer
  std::vector<Point3> all = L;
  all.insert(all.end(), B.begin(), B.end());
  const Camera cam(v, middle(all));
  dr::Figure f;
  draw_hull(f, L, t2::convex_hull_3d(L), cam, [](std::size_t) { return pal::blue; });
  for (std::size_t i = 0; i < A.size(); ++i) {
    f.segment(cam.at(B[i]), cam.at(L[i]), dr::Style().color(pal::light_grey).width(0.8).dash({2, 3}).layer(-1));
    f.add(cam.at(B[i]), dr::Style().size(2).color(pal::grey).layer(2));
    f.add(cam.at(L[i]), dr::Style().size(3).label("p\u0302" + std::to_string(i)).layer(2));
  }
  dr::save(f, cam.plane(all), dir / "lifted.svg");
}

void horizon_figure(const std::filesystem::path& dir) {
  const std::vector<Point3> H = cube_points(14, 5);
  const Point3 c = middle(H), p{c.x + 1.7, c.y + 0.6, c.z + 1.3};
  std::vector<Point3> P = H;
  P.push_back(p);
  const std::vector<Triangle3> T = t2::convex_hull_3d(H);
  std::vector<bool> visible;
  const Camera cam(view_from(minus(p, c), 95, 25), middle(P));
  // edge a -> b of a face: (the face is seen from p, the face is turned to the viewer)
  std::map<std::pair<std::uint32_t, std::uint32_t>, std::pair<bool, bool>> directed;
  for (const Triangle3& t : T) {
    visible.push_back(t2::orient3d(H[t[0]], H[t[1]], H[t[2]], p) > 0);
    for (int k = 0; k < 3; ++k)
      directed[{t[k], t[(k + 1) % 3]}] = {visible.back(), cam.sees(H[t[0]], H[t[1]], H[t[2]])};
  }
  dr::Figure f;
  draw_hull(f, H, T, cam, [&](std::size_t k) { return visible[k] ? pal::orange : pal::blue; });
  std::size_t horizon = 0;
  for (const auto& [e, flags] : directed) {  // a horizon edge: seen from p, its twin not
    const auto twin = directed.at({e.second, e.first});
    if (!flags.first || twin.first) continue;
    ++horizon;
    dr::Style st = dr::Style().color(pal::red).width(3).layer(2);
    if (!flags.second && !twin.second) st.width(2).dash({5, 3});  // behind the hull
    f.segment(cam.at(H[e.first]), cam.at(H[e.second]), st);
    f.segment(cam.at(p), cam.at(H[e.first]), dr::Style().color(pal::orange).width(1).dash({3, 3}).layer(1));
  }
  check08(horizon >= 3, "the horizon is a cycle");
  f.add(cam.at(p), dr::Style().size(3.5).label("p").label_angle(45).layer(3));
  dr::save(f, cam.plane(P), dir / "horizon.svg");
}

void gift_wrap_figure(const std::filesystem::path& dir) {
  const std::vector<Point3> P = cube_points(12, 4);
  const std::vector<Triangle3> T = t2::convex_hull_3d(P);
  const Triangle3 f0 = T[0];
  const std::uint32_t a = f0[0], b = f0[1], c = f0[2];
  std::uint32_t q = static_cast<std::uint32_t>(P.size());  // the facet across a b: (b, a, q)
  for (const Triangle3& t : T)
    for (int k = 0; k < 3; ++k)
      if (t[k] == b && t[(k + 1) % 3] == a) q = t[(k + 2) % 3];
  check08(q < P.size(), "a facet across the pivot edge");
  auto beyond = [&](std::uint32_t r) {  // how many points lie beyond the plane (b, a, r)
    int n = 0;
    for (const Point3& x : P) n += t2::orient3d(P[b], P[a], P[r], x) > 0;
    return n;
  };
  check08(beyond(q) == 0, "the wrap's facet has every point on its inner side");
  std::uint32_t r = q;  // the runner-up: only q lies beyond its plane
  for (std::uint32_t i = 0; i < P.size() && r == q; ++i)
    if (i != a && i != b && i != q && beyond(i) == 1) r = i;
  check08(r != q, "a runner-up candidate");
  const Point3 n1 = cross(minus(P[b], P[a]), minus(P[c], P[a])), n2 = cross(minus(P[a], P[b]), minus(P[q], P[b]));
  const Camera cam(view_from({n1.x / std::sqrt(dot(n1, n1)) + n2.x / std::sqrt(dot(n2, n2)),
                              n1.y / std::sqrt(dot(n1, n1)) + n2.y / std::sqrt(dot(n2, n2)),
                              n1.z / std::sqrt(dot(n1, n1)) + n2.z / std::sqrt(dot(n2, n2))},
                             30, 15),
                   middle(P));
  dr::Figure f;
  const Point A = cam.at(P[a]), B = cam.at(P[b]);
  f.add(std::vector<Point>{A, B, cam.at(P[c])}, dr::Style().color(pal::blue).width(1.4).fill(pal::blue).fill_opacity(0.3));
  f.add(std::vector<Point>{B, A, cam.at(P[r])}, dr::Style().color(pal::grey).width(1).dash({4, 3}));
  f.add(std::vector<Point>{B, A, cam.at(P[q])},
        dr::Style().color(pal::orange).width(1.4).fill(pal::orange).fill_opacity(0.3));
  const Point mid = Point::cartesian((A.x() + B.x()) / 2, (A.y() + B.y()) / 2);
  for (std::uint32_t i = 0; i < P.size(); ++i)
    if (i != a && i != b && i != c)
      f.segment(mid, cam.at(P[i]), dr::Style().color(pal::light_grey).width(0.8).dash({2, 3}).layer(-1));
  f.segment(A, B, dr::Style().color(pal::red).width(3).layer(1));
  for (const Point3& x : P) f.add(cam.at(x), dr::Style().size(2.5).color(pal::grey).layer(2));
  const std::pair<std::uint32_t, const char*> named[] = {{a, "a"}, {b, "b"}, {c, "c"}, {q, "p"}, {r, "r"}};
  for (const auto& [i, name] : named) f.add(cam.at(P[i]), dr::Style().size(3).label(name).layer(3));
  dr::save(f, cam.plane(P), dir / "gift-wrap.svg");
}

}  // namespace chapter08
