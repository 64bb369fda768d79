// Chapter 01, the oriented projective plane T²: T¹ and T², signed homogeneous coordinates,
// front, back and Ω, antipodes, why orientation needs the signs, and the two models.
//
// Prints every number the chapter quotes and writes its figures (planar and spherical model,
// and the two models of T¹) into --figures DIR. Deterministic. Every printed fact that the
// library decides (equality, side, orientation) is checked here against a second, independent
// computation with exact integers; a disagreement aborts the program.
#include <t2/t2.hpp>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <string>
#include <tuple>
#include <vector>

namespace {

using t2::ExactPoint;
using t2::Integer;
using t2::Point;
namespace dr = t2::draw;
namespace pal = t2::draw::palette;

const char* sym(t2::Sign s) { return t2::to_symbol(s); }

const char* side_name(t2::Side s) {
  switch (s) {
    case t2::Side::front: return "front";
    case t2::Side::back: return "back";
    default: return "on Omega";
  }
}

// Stops the program when an independent check fails: the text must never quote a wrong number.
void require(bool ok, const char* what) {
  if (!ok) {
    std::fprintf(stderr, "chapter_01: check failed: %s\n", what);
    std::exit(1);
  }
}

// Fixed-point text with `digits` decimals (the chapter quotes these numbers).
std::string fixed(double v, int digits = 4) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*f", digits, v == 0 ? 0.0 : v);
  return buf;
}

// ---------------------------------------------------------------------------------------------
// 1. The oriented projective line T¹.

void line_t1(const std::filesystem::path& dir) {
  std::cout << "== 1. The oriented projective line T1\n";
  //> t1-points
  const t2::T1 a(2, 6);    // [2, 6]: the front point 6/2 = 3
  const t2::T1 b(1, 3);    // [1, 3]: the same point (a positive multiple)
  const t2::T1 c(-1, -3);  // [-1, -3]: the back point "3", the antipode of b
  const t2::T1 up = t2::T1::plus_infinity(), down = t2::T1::minus_infinity();
  //< t1-points
  std::cout << "a = " << t2::to_string(a) << "  b = " << t2::to_string(b) << "  c = " << t2::to_string(c) << '\n';
  std::cout << "a == b: " << (a == b) << "   b == c: " << (b == c) << "   c == antipode(b): " << (c == t2::antipode(b))
            << '\n';
  std::cout << "side_of: a " << sym(t2::side_of(a)) << ", c " << sym(t2::side_of(c)) << ", +inf "
            << sym(t2::side_of(up)) << ", -inf " << sym(t2::side_of(down)) << '\n';
  // In P¹ the pairs [w, x] and [λw, λx] are one point for every λ ≠ 0: b and c would be equal.
  // The independent check: a 2x2 determinant and the sign of the ratio of the weights.
  require(a == b && !(b == c), "T1 equality");
  require(Integer(1 * -3 - 3 * -1) == 0, "b and c are proportional (equal in P1)");
  // Orientation in T¹: the sign of |a; d| tells whether d follows a counter-clockwise on the
  // circle model, within half a turn.
  const t2::T1 five(1, 5);
  std::cout << "orient(b, [1,5]) = " << sym(t2::orient(b, five)) << "   orient(c, [1,5]) = " << sym(t2::orient(c, five))
            << "   orient(b, +inf) = " << sym(t2::orient(b, up)) << '\n';
  require(t2::orient(b, five) == t2::POSITIVE && t2::orient(c, five) == t2::NEGATIVE, "T1 orientation");

  dr::Figure fig;
  fig.add(b, dr::Style().label("[1,3] = [2,6]").color(pal::blue));
  fig.add(c, dr::Style().label("[-1,-3]").color(pal::red));
  fig.add(up, dr::Style());    // the view labels +inf and -inf itself
  fig.add(down, dr::Style());
  fig.add(t2::T1(1, 0), dr::Style().label("0 = [1,0]").color(pal::green));
  fig.add(t2::T1(-1, 0), dr::Style().label("[-1,0]").color(pal::green));
  dr::T1View circle;
  circle.model = dr::T1Model::circle;
  dr::save(fig, circle, dir / "t1-circle.svg");
  dr::T1View lines;
  lines.model = dr::T1Model::lines;
  lines.half_width = 5;
  dr::save(fig, lines, dir / "t1-lines.svg");
}

// ---------------------------------------------------------------------------------------------
// 2. Points of T²: signed homogeneous coordinates, front, back, Ω, antipodes.

struct Named {
  const char* name;
  Point p;
};

void points_t2(const std::filesystem::path& dir) {
  std::cout << "\n== 2. Points of T2\n";
  //> t2-points
  const Point p(1, 2, 1);      // front: Cartesian (2, 1)
  const Point q(2, 4, 2);      // the same point as p: q = 2p
  const Point np(-1, -2, -1);  // the antipode of p: back side, also "at" (2, 1)
  const Point s(-2, 1, 3);     // back: drawn at (1/-2, 3/-2) = (-0.5, -1.5)
  const Point d(0, 1, 1);      // on Omega: the direction (1, 1)
  const Point nd(0, -1, -1);   // on Omega: the opposite direction (-1, -1)
  //< t2-points
  const std::vector<Named> pts = {{"p", p}, {"q", q}, {"np", np}, {"s", s}, {"d", d}, {"nd", nd}};
  std::cout << "name  [w, x, y]      side      Cartesian        sphere (x, y, w)/|.|\n";
  for (const auto& [name, pt] : pts) {
    const auto c = t2::to_cartesian(pt);
    const double n = std::sqrt(pt.w() * pt.w() + pt.x() * pt.x() + pt.y() * pt.y());
    std::string cart = c ? "(" + t2::to_string(c->first) + ", " + t2::to_string(c->second) + ")" : "none";
    std::printf("%-4s  %-13s  %-8s  %-15s  (%s, %s, %s)\n", name, t2::to_string(pt).c_str(),
                side_name(t2::side_of(pt)), cart.c_str(), fixed(pt.x() / n).c_str(), fixed(pt.y() / n).c_str(),
                fixed(pt.w() / n).c_str());
  }
  std::cout << "p == q: " << (p == q) << "   p == np: " << (p == np) << "   np == antipode(p): " << (np == t2::antipode(p))
            << "   d == nd: " << (d == nd) << '\n';
  // Independent check of equality: q = λp with λ > 0 exactly when all 2x2 minors vanish and
  // the dot product is positive; done here on exact integers.
  auto same = [](const ExactPoint& u, const ExactPoint& v) {
    return u.w() * v.x() - u.x() * v.w() == 0 && u.w() * v.y() - u.y() * v.w() == 0 &&
           u.x() * v.y() - u.y() * v.x() == 0 && u.w() * v.w() + u.x() * v.x() + u.y() * v.y() > 0;
  };
  require(same(t2::to_exact(p), t2::to_exact(q)) == (p == q), "p == q");
  require(same(t2::to_exact(p), t2::to_exact(np)) == (p == np), "p == np");
  require(same(t2::to_exact(d), t2::to_exact(nd)) == (d == nd), "d == nd");
  require(t2::side_of(s) == t2::Side::back && t2::side_of(d) == t2::Side::infinity, "sides");

  dr::Figure fig;
  fig.add(p, dr::Style().label("p = [1,2,1]").color(pal::blue));
  fig.add(np, dr::Style().label("¬p").label_angle(-45).color(pal::red));
  fig.add(s, dr::Style().label("s = [-2,1,3]").label_angle(-60).color(pal::red));
  fig.add(d, dr::Style().label("d = [0,1,1]").color(pal::green));
  fig.add(nd, dr::Style().label("¬d").label_angle(-135).color(pal::green));
  dr::PlaneView plane;
  plane.half_width = 3;
  plane.axes = true;
  dr::SphereView sphere;
  sphere.lat = 25;
  sphere.lon = -60;
  dr::save(fig, plane, dir / "points-plane.svg");
  dr::save(fig, sphere, dir / "points-sphere.svg");
}

// ---------------------------------------------------------------------------------------------
// 3. Orientation needs the signs.

void orientation(const std::filesystem::path& dir) {
  std::cout << "\n== 3. Orientation needs the signs\n";
  //> orient-signs
  const ExactPoint a(1, 0, 0), b(1, 4, 0),
      c(1, 0, 3);  // a counter-clockwise front triangle
  const Integer det =
      t2::det3(a.w(), a.x(), a.y(), b.w(), b.x(), b.y(), c.w(), c.x(), c.y());
  std::cout << "det(a, b, c) = " << det
            << "   orient(a, b, c) = " << sym(t2::orient(a, b, c)) << '\n';
  std::cout << "orient(5a, b, c) = " << sym(t2::orient(ExactPoint(5, 0, 0), b, c))
            << "   orient(antipode(a), b, c) = " << sym(t2::orient(t2::antipode(a), b, c))
            << '\n';
  std::cout << "orient(antipode(a), antipode(b), antipode(c)) = "
            << sym(t2::orient(t2::antipode(a), t2::antipode(b), t2::antipode(c))) << '\n';
  //< orient-signs
  // Independent check: the determinant by the rule of Sarrus, on plain integers.
  const long sarrus = 1 * 4 * 3 + 0 * 0 * 1 + 0 * 1 * 0 - 0 * 4 * 1 - 0 * 1 * 3 - 1 * 0 * 0;
  require(det == sarrus && sarrus == 12, "det(a, b, c) = 12");
  require(t2::orient(t2::antipode(a), b, c) == t2::NEGATIVE, "antipode flips orientation");
  require(t2::orient(t2::antipode(a), t2::antipode(b), t2::antipode(c)) == t2::NEGATIVE, "back triangle");
  // The same facts with double coordinates (the library is generic over the coordinate type).
  require(t2::orient(Point(1, 0, 0), Point(1, 4, 0), Point(1, 0, 3)) == t2::POSITIVE, "double orient");

  dr::Figure fig;
  const std::vector<ExactPoint> tri = {a, b, c};
  const std::vector<ExactPoint> back = {t2::antipode(a), t2::antipode(b), t2::antipode(c)};
  fig.add(tri, dr::Style().color(pal::blue).fill(pal::blue));
  fig.add(back, dr::Style().color(pal::red).fill(pal::red).fill_opacity(0.12));
  fig.arrow(a, b, dr::Style().color(pal::blue).width(2.2));
  fig.arrow(b, c, dr::Style().color(pal::blue).width(2.2));
  fig.arrow(c, a, dr::Style().color(pal::blue).width(2.2));
  fig.add(a, dr::Style().label("a").label_angle(-135));
  fig.add(b, dr::Style().label("b").label_angle(-45));
  fig.add(c, dr::Style().label("c").label_angle(135));
  dr::PlaneView plane;
  plane.cx = 1.5;
  plane.cy = 1.2;
  plane.half_width = 3.5;
  dr::SphereView sphere;
  sphere.lat = 35;
  sphere.lon = -50;
  dr::save(fig, plane, dir / "orient-plane.svg");
  dr::save(fig, sphere, dir / "orient-sphere.svg");
}

// ---------------------------------------------------------------------------------------------
// 4. Lines, Ω, and parallel lines that meet.

void parallels(const std::filesystem::path& dir) {
  std::cout << "\n== 4. Lines, Omega and parallels\n";
  //> parallels
  const t2::Line l =
      t2::join(Point(1, 0, 0), Point(1, 1, 0));  // y = 0, oriented towards +x
  const t2::Line m = t2::join(Point(1, 0, 1), Point(1, 1, 1));  // y = 1, also towards +x
  const Point x = t2::meet(l, m);                               // where they meet
  std::cout << "l = " << t2::to_string(l) << "   m = " << t2::to_string(m)
            << "   meet(l, m) = " << t2::to_string(x) << " (" << side_name(t2::side_of(x))
            << ")\n";
  std::cout << "meet(m, l) = " << t2::to_string(t2::meet(m, l))
            << "   Omega = " << t2::to_string(t2::omega())
            << "   side(Omega, p) for p = [1,2,1], [-2,1,3], [0,1,1]: "
            << sym(t2::side(t2::omega(), Point(1, 2, 1))) << ' '
            << sym(t2::side(t2::omega(), Point(-2, 1, 3))) << ' '
            << sym(t2::side(t2::omega(), Point(0, 1, 1))) << '\n';
  //< parallels
  // Independent check: the cross product of the coefficient triples, by hand, on integers.
  const ExactPoint lx(0, 0, 1), mx(-1, 0, 1);  // <W,X,Y> of l and m as triples
  const ExactPoint cross(lx.x() * mx.y() - lx.y() * mx.x(), lx.y() * mx.w() - lx.w() * mx.y(),
                         lx.w() * mx.x() - lx.x() * mx.w());
  require(t2::to_exact(x) == cross, "meet(l, m) is the cross product");
  require(t2::to_exact(Point(l.W(), l.X(), l.Y())) == lx && t2::to_exact(Point(m.W(), m.X(), m.Y())) == mx,
          "join of the two pairs");
  require(t2::side_of(x) == t2::Side::infinity, "parallels meet on Omega");

  dr::Figure fig;
  fig.add(l, dr::Style().color(pal::blue).arrow().label("l"));
  fig.add(m, dr::Style().color(pal::orange).arrow().label("m"));
  fig.add(x, dr::Style().label("meet(l, m)").color(pal::green));
  fig.add(t2::antipode(x), dr::Style().label("meet(m, l)").label_angle(135).color(pal::green));
  dr::PlaneView plane;
  plane.half_width = 3;
  plane.axes = true;
  dr::SphereView sphere;
  sphere.lat = 30;
  sphere.lon = -30;
  dr::save(fig, plane, dir / "parallels-plane.svg");
  dr::save(fig, sphere, dir / "parallels-sphere.svg");
}

// ---------------------------------------------------------------------------------------------
// 5. The two sides of a line in both models.

void sides(const std::filesystem::path& dir) {
  std::cout << "\n== 5. The two sides of a line\n";
  //> sides
  const t2::Line l(-1, 1, 1);  // the points with -w + x + y = 0: the front line x + y = 1
  for (const Point& r : {Point(1, 1, 1), Point(-1, -1, -1), Point(1, 0, 0),
                         Point(-1, 0, 0), Point(0, 1, 0), Point(0, -1, 1)})
    std::cout << "side(l, " << t2::to_string(r) << ") = " << sym(t2::side(l, r)) << '\n';
  //< sides
  require(t2::side(l, Point(1, 1, 1)) == t2::POSITIVE && t2::side(l, Point(-1, -1, -1)) == t2::NEGATIVE,
          "antipodes lie on opposite sides");
  require(t2::side(l, Point(0, -1, 1)) == t2::ZERO, "the direction (-1, 1) of l is on l");
  // The labels of the figure: -w + x + y on integers.
  require(-(-1) + 1 + 2 > 0 && t2::side(l, Point(-1, 1, 2)) == t2::POSITIVE, "[-1,1,2] is on the positive side");
  require(-1 + 0 + 0 < 0 && t2::side(l, Point(1, 0, 0)) == t2::NEGATIVE, "[1,0,0] is on the negative side");

  dr::Figure fig;
  fig.add(l, dr::Style().color(pal::blue).shade().fill(pal::blue).arrow().label("l"));
  fig.add(Point(1, 1, 1), dr::Style().label("[1,1,1] +"));
  fig.add(Point(-1, 1, 2), dr::Style().label("[-1,1,2] +").label_angle(-45));  // back, drawn at (-1, -2)
  fig.add(Point(1, 0, 0), dr::Style().label("[1,0,0] -").label_angle(-135));
  dr::PlaneView plane;
  plane.half_width = 3;
  plane.axes = true;
  dr::SphereView sphere;
  sphere.lat = 30;
  sphere.lon = -40;
  dr::save(fig, plane, dir / "sides-plane.svg");
  dr::save(fig, sphere, dir / "sides-sphere.svg");
}

// ---------------------------------------------------------------------------------------------
// 6. Duality.

void duality(const std::filesystem::path& dir) {
  std::cout << "\n== 6. Duality\n";
  //> duality-demo
  const ExactPoint p(1, 1, 0), q(2, 1, 1),
      r(1, 0, 1);  // three points of the line x + y = 1
  const t2::ExactLine P = t2::dual(p), Q = t2::dual(q),
                      R = t2::dual(r);  // their dual lines
  const ExactPoint z = t2::meet(P, Q);
  std::cout << "orient(p, q, r) = " << sym(t2::orient(p, q, r))
            << "   P = " << t2::to_string(P) << "  Q = " << t2::to_string(Q)
            << "  R = " << t2::to_string(R) << "\n";
  std::cout << "meet(P, Q) = " << t2::to_string(z) << "   side(R, meet(P, Q)) = "
            << sym(t2::side(R, z)) << "   dual(join(p, q)) == meet(P, Q): "
            << (t2::dual(t2::join(p, q)) == z) << "\n";
  //< duality-demo
  require(t2::orient(p, q, r) == t2::ZERO && t2::side(R, z) == t2::ZERO, "collinear <-> concurrent");
  const ExactPoint s(1, 1, 2);
  std::cout << "side(P, s) = " << sym(t2::side(P, s)) << " = side(dual(s), dual(P)) = "
            << sym(t2::side(t2::dual(s), t2::dual(P))) << "\n";
  require(t2::side(P, s) == t2::side(t2::dual(s), t2::dual(P)), "duality keeps sides");

  dr::Figure fig;
  fig.add(t2::join(p, r), dr::Style().color(pal::light_grey).label("join(p, r)"));
  for (const auto& [pt, name, colour] : {std::tuple{p, "p", pal::blue}, std::tuple{q, "q", pal::green},
                                        std::tuple{r, "r", pal::red}}) {
    fig.add(pt, dr::Style().color(colour).label(name));
    fig.add(t2::dual(pt), dr::Style().color(colour).dash({5, 3}));
  }
  fig.add(z, dr::Style().color(pal::black).marker(dr::Marker::square).label("meet(P, Q)"));
  dr::PlaneView plane;
  plane.half_width = 3;
  plane.axes = true;
  dr::SphereView sphere;
  sphere.lat = 35;
  sphere.lon = -30;
  dr::save(fig, plane, dir / "duality-plane.svg");
  dr::save(fig, sphere, dir / "duality-sphere.svg");
}

// ---------------------------------------------------------------------------------------------
// 7. A map that sends a line to Omega: perspective, and clipping behind the eye.

void perspective(const std::filesystem::path& dir) {
  std::cout << "\n== 7. Perspective: a line sent to Omega\n";
  //> perspective-map
  // The eye is the origin and looks along +y; the image line is y = 1. M sends [w, x, y]
  // to [y, x, -w]: a front point (x, y) goes to (x/y, -1/y), whose first coordinate is
  // where the ray from the eye through it meets the image line. The eye's line y = 0 goes
  // to Omega.
  const t2::ExactAffine M({{{0, 0, 1}, {0, 1, 0}, {-1, 0, 0}}});
  //< perspective-map
  //> perspective-demo
  const ExactPoint a = ExactPoint::cartesian(-1, 2),
                   b = ExactPoint::cartesian(2, -1);  // b: behind
  const ExactPoint Ma = t2::transform(M, a), Mb = t2::transform(M, b);
  const t2::ExactSegment image = t2::transform(M, t2::ExactSegment(a, b));
  std::cout << "det M = " << sym(M.determinant_sign()) << "   M(<0, 0, 1>) = "
            << t2::to_string(t2::transform(M, t2::ExactLine(0, 0, 1))) << "\n";
  std::cout << "M a = " << t2::to_string(Ma) << " (" << side_name(t2::side_of(Ma))
            << ")   M b = " << t2::to_string(Mb) << " (" << side_name(t2::side_of(Mb))
            << ")\n";
  std::cout << "image of segment ab leaves the front at "
            << t2::to_string(t2::point_at_infinity(image))
            << "; the front part runs from u = -1/2 to u = +infinity\n";
  //< perspective-demo
  require(M.determinant_sign() == t2::POSITIVE && t2::transform(M, t2::ExactLine(0, 0, 1)) == t2::omega<Integer>(),
          "M keeps orientation and sends y = 0 to Omega");
  require(t2::side_of(Ma) == t2::Side::front && t2::side_of(Mb) == t2::Side::back, "front and behind");
  // The crossing of ab with the eye's line is (1, 0); its image is the direction (1, -1): the
  // image coordinate x/y grows without bound as a point of ab approaches (1, 0) from the front.
  require(t2::point_at_infinity(image) == ExactPoint(0, 1, -1), "ab leaves through [0, 1, -1]");
  require(t2::on_segment(a, b, ExactPoint::cartesian(1, 0)), "ab crosses y = 0 at (1, 0)");
  // The classical (unsigned) projective view divides by y alone: b "appears" at u = x/y = -2.
  std::cout << "dividing without the sign puts b at u = " << b.x() * b.w() << "/" << b.y() * b.w()
            << " = -2, in front of the eye\n";

  dr::Figure scene;
  scene.add(t2::ExactLine(0, 0, 1), dr::Style().color(pal::light_grey).dash({5, 3}).label("eye's line"));
  scene.add(t2::ExactLine(-1, 0, 1), dr::Style().color(pal::pale_grey).label("image line"));
  scene.segment(a, ExactPoint::cartesian(1, 0), dr::Style().color(pal::green).width(2));
  scene.segment(ExactPoint::cartesian(1, 0), b, dr::Style().color(pal::red).width(2).dash({4, 3}));
  scene.add(ExactPoint::cartesian(0, 0), dr::Style().marker(dr::Marker::square).label("eye"));
  scene.add(a, dr::Style().label("a"));
  scene.add(b, dr::Style().label("b (behind)"));
  dr::Figure img;
  img.add(t2::transform(M, t2::ExactLine(-1, 0, 1)), dr::Style().color(pal::pale_grey).label("M(image line)"));
  img.segment(Ma, t2::point_at_infinity(image), dr::Style().color(pal::green).width(2));
  img.segment(t2::point_at_infinity(image), Mb, dr::Style().color(pal::red).width(2).dash({4, 3}));
  img.add(Ma, dr::Style().label("M a"));
  img.add(Mb, dr::Style().label("M b"));
  img.add(t2::point_at_infinity(image), dr::Style().color(pal::red).label("M (1, 0)"));
  dr::PlaneView plane;
  plane.half_width = 3;
  plane.axes = true;
  dr::SphereView sphere;
  sphere.lat = 30;
  sphere.lon = -50;
  dr::save(scene, plane, dir / "perspective-scene-plane.svg");
  dr::SphereView high = sphere;  // from higher up: a and b both on the near hemisphere
  high.lat = 55;
  high.lon = 45;
  dr::save(scene, high, dir / "perspective-scene-sphere.svg");
  dr::save(img, plane, dir / "perspective-image-plane.svg");
  dr::save(img, sphere, dir / "perspective-image-sphere.svg");
}

}  // namespace

int main(int argc, char** argv) {
  const std::filesystem::path dir = dr::figures_dir(argc, argv, T2_FIGURES_DIR);
  std::cout << std::boolalpha;  // equality tests print true / false
  line_t1(dir);
  points_t2(dir);
  orientation(dir);
  parallels(dir);
  sides(dir);
  duality(dir);
  perspective(dir);
  return 0;
}
