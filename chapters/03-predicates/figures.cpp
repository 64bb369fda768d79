// Chapter 03: the figures of sections 1, 5 and 6 (orientation, the sweep test, midpoints), then
// those of section 8 (circles.cpp). Called from main.cpp, which passes the naive midpoint its
// listing shows.
#include <t2/t2.hpp>
#include <t2/kernel/midpoint.hpp>

#include <filesystem>
#include <iostream>
#include <utility>

namespace chapter03 {

void circle_figures(const std::filesystem::path& dir, int& written);  // circles.cpp
using Midpoint = t2::ExactPoint (*)(const t2::ExactPoint&, const t2::ExactPoint&);

namespace {
using t2::ExactPoint;
using t2::Point;
namespace dr = t2::draw;
namespace pal = t2::draw::palette;
}  // namespace

void figures(const std::filesystem::path& dir, Midpoint naive_midpoint) {
  dr::PlaneView plane;
  plane.half_width = 3;
  dr::SphereView sphere;
  int written = 0;
  {  // Orientation: p, q, r and the back point s = ¬r, with the positive side of p ∨ q shaded.
    const Point p(1, 0, 0), q(1, 2, 0), r(1, 1, 1), s(-1, -1, -1);
    dr::Figure f;
    f.add(t2::join(p, q), dr::Style().color(pal::grey).shade().arrow());
    f.segment(p, q, dr::Style().width(2.2));
    f.add(p, dr::Style().label("p").label_angle(-135));
    f.add(q, dr::Style().label("q").label_angle(-45));
    f.add(r, dr::Style().color(pal::blue).label("r"));
    f.add(s, dr::Style().color(pal::red).label("s = \u00acr").label_angle(135));
    written += dr::save(f, plane, dir / "orient-plane.svg");
    written += dr::save(f, sphere, dir / "orient-sphere.svg");
  }
  {  // Midpoints: naive (red) against the seed's formula (green), for the three cases.
    const ExactPoint f1 = ExactPoint::cartesian(0, 0), f2(2, 4, 2), b1(-1, -2, 2), b2(-2, 0, -4);
    dr::Figure f;
    const std::pair<ExactPoint, ExactPoint> pairs[3] = {{f1, f2}, {b1, b2}, {f1, b1}};
    const char* names[3][2] = {{"p1", "q1"}, {"p2", "q2"}, {"", "q3"}};
    int k = 0;
    for (const auto& [p, q] : pairs) {
      f.segment(p, q, dr::Style().color(pal::dark_grey));
      f.add(p, dr::Style().label(names[k][0]).label_angle(-135));
      f.add(q, dr::Style().label(names[k][1]));
      ++k;
      f.add(t2::midpoint(p, q), dr::Style().color(pal::green).marker(dr::Marker::square).size(5));
      f.add(naive_midpoint(p, q), dr::Style().color(pal::red).marker(dr::Marker::cross).size(5));
    }
    dr::PlaneView wide = plane;  // room for the back half-ray of the front-back segment
    wide.half_width = 5;
    written += dr::save(f, wide, dir / "midpoint-plane.svg");
    written += dr::save(f, sphere, dir / "midpoint-sphere.svg");
  }
  {  // The sweep test: a, b proper, c at infinity; r⊥ through a, normal to a ∨ c.
    const ExactPoint a = ExactPoint::cartesian(0, 0), b = ExactPoint::cartesian(1, 1), c(0, 2, 1);
    const t2::ExactLine r = t2::join(a, c);
    const t2::ExactLine rp = t2::join(a, ExactPoint(0, r.X(), r.Y()));
    dr::Figure f;
    f.add(r, dr::Style().color(pal::light_grey).arrow());
    f.add(rp, dr::Style().color(pal::blue).shade());
    f.add(a, dr::Style().label("a"));
    f.add(b, dr::Style().label("b"));
    f.add(c, dr::Style().color(pal::red).label("c"));
    written += dr::save(f, plane, dir / "sweep-plane.svg");
    written += dr::save(f, sphere, dir / "sweep-sphere.svg");
  }
  circle_figures(dir, written);
  std::cout << "figures: 10 in " << dir.filename().string() << "\n";
  std::cerr << written << " figure file(s) rewritten\n";  // depends on the directory: not stdout
}

}  // namespace chapter03
