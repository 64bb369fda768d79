// Chapter 03, section 8: circles and disks of every radius kind, the order of distances beyond
// infinity, and the in-circle test. Called from main.cpp; prints what the chapter quotes and
// draws the figures distance-order-* and incircle-*.
#include <t2/t2.hpp>
#include <t2/kernel/distance.hpp>
#include <t2/kernel/incircle.hpp>

#include <cmath>
#include <filesystem>
#include <iostream>
#include <stdexcept>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

namespace chapter03 {

namespace {

using t2::ExactPoint;
using t2::Integer;
using t2::Sign;
namespace dr = t2::draw;
namespace pal = t2::draw::palette;

const char* sym(Sign s) { return t2::to_symbol(s); }
std::string str(const ExactPoint& p) { return t2::to_string(p); }

void require(bool ok, const std::string& what) {
  if (!ok) throw std::logic_error("chapter 03 check failed: " + what);
}

// The points of the distance-order example: c = the front origin, then points ever farther.
std::vector<ExactPoint> order_points() {
  return {ExactPoint(1, 1, 0),    ExactPoint(1, 3, 0),  ExactPoint(0, 1, 1),
          ExactPoint(-1, 0, -5),  ExactPoint(-1, 0, 1),  ExactPoint(-1, 0, 0)};
}

// The spherical angle between two points of T² (the oracle of the order around the origin).
long double sphere_angle(const ExactPoint& a, const ExactPoint& b) {
  const long double aw = a.w().get_d(), ax = a.x().get_d(), ay = a.y().get_d();
  const long double bw = b.w().get_d(), bx = b.x().get_d(), by = b.y().get_d();
  const long double dot = aw * bw + ax * bx + ay * by;
  const long double cx = ax * by - ay * bx, cy = ay * bw - aw * by, cz = aw * bx - ax * bw;
  return std::atan2(std::sqrt(cx * cx + cy * cy + cz * cz), dot);
}

}  // namespace

void circles() {
  std::cout << "== 8. Circles, disks and the in-circle test\n";
  //> distance-order
  const ExactPoint c(1, 0, 0);  // the front origin
  std::cout << "d2(c, p) for the points 1 to 6:";
  for (const ExactPoint& p : order_points())
    std::cout << " " << t2::to_string(t2::squared_distance(c, p));
  std::cout << "\n";
  const t2::ExactT1 five = t2::squared_distance(c, ExactPoint(-1, 0, -5));  // back, 5 away
  const t2::ExactT1 one = t2::squared_distance(c, ExactPoint(-1, 0, 1));    // back, 1 away
  std::cout << "compare(back at 5, back at 1) = "
            << sym(t2::compare_distance_values(five, one))
            << "   compare(back at 1, antipode) = "
            << sym(t2::compare_distance_values(one,
                                               t2::squared_distance(c, t2::antipode(c))))
            << "\n";
  //< distance-order
  const std::vector<ExactPoint> ranked = order_points();
  for (std::size_t i = 0; i + 1 < ranked.size(); ++i)
    require(t2::compare_distance_values(t2::squared_distance(c, ranked[i]),
                                        t2::squared_distance(c, ranked[i + 1])) == t2::NEGATIVE,
            "the points 1 to 6 are in increasing distance");
  // Around the origin the T¹ order of d² is the order of the angle on the sphere; from any
  // proper centre, d²(¬z, p) is d²(z, p) with its weight negated, which reverses the order.
  std::vector<ExactPoint> grid;
  for (int w = -1; w <= 1; ++w)
    for (int x = -2; x <= 2; ++x)
      for (int y = -2; y <= 2; ++y)
        if (w != 0 || x != 0 || y != 0) grid.push_back(ExactPoint(w, x, y));
  int pairs = 0, sphere_ok = 0, reversed = 0, reverse_pairs = 0;
  const ExactPoint z(1, 1, -1);
  for (const auto& p : grid)
    for (const auto& q : grid) {
      ++pairs;
      const long double d = sphere_angle(c, p) - sphere_angle(c, q);
      const Sign want = std::fabs(d) < 1e-12L ? t2::ZERO : (d > 0 ? t2::POSITIVE : t2::NEGATIVE);
      sphere_ok += t2::compare_distance_values(t2::squared_distance(c, p), t2::squared_distance(c, q)) == want;
      if (p.w() == 0 || q.w() == 0) continue;
      ++reverse_pairs;
      const Sign near = t2::compare_distance_values(t2::squared_distance(z, p), t2::squared_distance(z, q));
      const Sign far = t2::compare_distance_values(t2::squared_distance(t2::antipode(z), p),
                                                   t2::squared_distance(t2::antipode(z), q));
      reversed += near == -far;
    }
  std::cout << "order of d2 from the origin = order of the angle on the sphere: " << sphere_ok << " of "
            << pairs << " pairs\n";
  std::cout << "nearer to z = (1, -1) <=> farther from antipode(z): " << reversed << " of " << reverse_pairs
            << " pairs of proper points\n";
  require(sphere_ok == pairs && reversed == reverse_pairs, "distance order");

  //> incircle-demo
  const ExactPoint a = ExactPoint::cartesian(1, 0), b = ExactPoint::cartesian(0, 1),
                   d = ExactPoint::cartesian(-1,
                                             0);  // counter-clockwise on the unit circle
  const ExactPoint queries[] = {ExactPoint::cartesian(0, 0), ExactPoint::cartesian(2, 0),
                                ExactPoint::cartesian(0, -1), ExactPoint(-1, 0, 0),
                                ExactPoint(0, 1, 0)};
  for (const ExactPoint& q : queries)
    std::cout << "q = " << str(q)
              << ": in_circle(a, b, d, q) = " << sym(t2::in_circle(a, b, d, q))
              << ", in_circle(a, d, b, q) = " << sym(t2::in_circle(a, d, b, q))
              << ", in_disk = " << sym(t2::in_disk(a, b, d, q)) << "\n";
  //< incircle-demo
  const ExactPoint na = t2::antipode(a), nb = t2::antipode(b), nd = t2::antipode(d);
  std::cout << "back triple: orient(~a, ~b, ~d) = " << sym(t2::orient(na, nb, nd))
            << ", in_circle(~a, ~b, ~d, [-1, 0, 0]) = " << sym(t2::in_circle(na, nb, nd, ExactPoint(-1, 0, 0)))
            << ", in_disk = " << sym(t2::in_disk(na, nb, nd, ExactPoint(-1, 0, 0))) << "\n";
  // a, b on the front and ~d on the back: no circle with a proper centre passes through them;
  // their circle is a lune centred on Omega (incircle.hpp), here the half-plane left of a -> b.
  std::cout << "in_circle(a, b, ~d, q) = " << sym(t2::in_circle(a, b, nd, queries[0])) << " (a lune)\n";
  // The oracle: the definition by distances. in_disk(a, b, d, q) is + iff d2(z, q) < d2(z, a)
  // for the centre z on the points' side, 0 iff equal; checked on a grid of both sides.
  int checked = 0, agree = 0;
  for (const auto& [p, r, s] : {std::tuple{a, b, d}, std::tuple{na, nd, nb},
                                std::tuple{ExactPoint::cartesian(0, 0), ExactPoint::cartesian(2, 1),
                                           ExactPoint(2, 1, 4)}}) {
    const ExactPoint centre = t2::circle_through(p, r, s).center();
    for (const auto& q : grid) {
      ++checked;
      const Sign by_distance =
          -t2::compare_distance_values(t2::squared_distance(centre, q), t2::squared_distance(centre, p));
      agree += t2::in_disk(p, r, s, q) == by_distance;
    }
  }
  std::cout << "in_disk == (d2(z, q) < d2(z, a)) on " << agree << " of " << checked << " grid points\n\n";
  require(agree == checked, "in_disk against distances");
}

void circle_figures(const std::filesystem::path& dir, int& written) {
  dr::PlaneView plane;
  plane.half_width = 6;
  dr::SphereView sphere;
  sphere.lat = 15;
  {  // The order of distances from c beyond infinity: ranks 1..6, the antipode last.
    const ExactPoint c(1, 0, 0);
    dr::Figure f;
    f.add(t2::ExactCircle(c, ExactPoint(-1, 0, 1)), dr::Style().color(pal::red).dash({4, 3}));
    f.add(t2::ExactCircle(c, ExactPoint(-1, 0, -5)), dr::Style().color(pal::orange).dash({4, 3}));
    f.add(c, dr::Style().color(pal::blue).label("c").label_angle(135));
    int rank = 1;
    for (const auto& p : order_points()) f.add(p, dr::Style().label(std::to_string(rank++)).label_angle(45));
    written += dr::save(f, plane, dir / "distance-order-plane.svg");
    written += dr::save(f, sphere, dir / "distance-order-sphere.svg");
  }
  {  // The in-circle test: the disk through a, b, d and the queries, coloured by in_disk.
    const ExactPoint a = ExactPoint::cartesian(1, 0), b = ExactPoint::cartesian(0, 1),
                     d = ExactPoint::cartesian(-1, 0);
    dr::Figure f;
    f.add(t2::circle_through(a, b, d), dr::Style().fill(pal::green).fill_opacity(0.15).arrow());
    for (const auto& [p, name] : {std::pair{a, "a"}, std::pair{b, "b"}, std::pair{d, "d"}})
      f.add(p, dr::Style().label(name));
    for (int x = -2; x <= 2; ++x)
      for (int y = -2; y <= 2; ++y)
        for (int w : {2, -2}) {
          const ExactPoint q(w, x, y);
          if (q == a || q == b || q == d) continue;
          const Sign s = t2::in_disk(a, b, d, q);
          f.add(q, dr::Style().size(2.5).color(s > 0 ? pal::green : (s < 0 ? pal::red : pal::black)));
        }
    dr::PlaneView near = plane;
    near.half_width = 1.6;
    written += dr::save(f, near, dir / "incircle-plane.svg");
    written += dr::save(f, sphere, dir / "incircle-sphere.svg");
  }
}

}  // namespace chapter03
