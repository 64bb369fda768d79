// Chapter 05, polygons: closest point on a segment, segment intersection from four (and, in T²,
// five) orientations, signed area, point in polygon by ray casting, by winding number and by
// Algorithm 2 of seed 000 §5.1, and ear clipping.
//
// Prints every number the chapter quotes and writes its figures, in the planar and the
// spherical model, into --figures DIR. Deterministic. The seed's Algorithm 2 is also run
// literally, next to the corrected t2::locate, to count where it goes wrong.
#include <t2/t2.hpp>

#include <filesystem>
#include <stdexcept>
#include <iostream>
#include <string>
#include <vector>

namespace {

using t2::ExactPoint;
using t2::ExactPolygon;
using t2::Point;
using t2::Sign;
namespace dr = t2::draw;
namespace pal = t2::draw::palette;

const char* sym(Sign s) { return t2::to_symbol(s); }
std::string str(const ExactPoint& p) { return t2::to_string(p); }
std::string cart(const ExactPoint& p) {  // "(x, y)" as exact fractions, or "at infinity"
  if (p.w() == 0) return "on Omega";
  t2::Rational x(p.x(), p.w()), y(p.y(), p.w());
  x.canonicalize();
  y.canonicalize();
  return "(" + x.get_str() + ", " + y.get_str() + ")";
}
ExactPoint P(long x, long y) { return ExactPoint::cartesian(x, y); }

// ---------------------------------------------------------------------------------------------
// 1. Closest point on a segment.

void closest_point() {
  std::cout << "== 1. Closest point on a segment\n";
  //> closest-demo
  const ExactPoint a = P(0, 0), b = P(4, 2);
  const ExactPoint q1 = P(1, 3), q2 = P(-2, 1), q3(2, 10, 6);  // q3 = (5, 3), weight 2
  for (const ExactPoint& q : {q1, q2, q3}) {
    const ExactPoint c = t2::closest_point_on_segment(a, b, q);
    std::cout << "q = " << cart(q) << "  ->  " << str(c) << " = " << cart(c) << "\n";
  }
  //< closest-demo
  std::cout << "on the back side: closest(~a, ~b, ~q1) = "
            << cart(t2::closest_point_on_segment(t2::antipode(a), t2::antipode(b), t2::antipode(q1)))
            << " (a back point; same Cartesian position)\n";
  try {
    (void)t2::closest_point_on_segment(a, b, ExactPoint(0, 1, 0));
  } catch (const t2::Undefined& e) {
    std::cout << "q on Omega: Undefined: " << e.what() << "\n";
  }
  std::cout << "\n";
}

// ---------------------------------------------------------------------------------------------
// 2. Segment intersection.

void intersection() {
  std::cout << "== 2. Segment intersection from orientations\n";
  //> four-orientations
  const ExactPoint a = P(-2, 0), b = P(2, 0), c = P(0, -2), d = P(0, 2);
  std::cout << "orient(a,b,c) = " << sym(t2::orient(a, b, c))
            << ", orient(a,b,d) = " << sym(t2::orient(a, b, d))
            << ", orient(c,d,a) = " << sym(t2::orient(c, d, a))
            << ", orient(c,d,b) = " << sym(t2::orient(c, d, b))
            << "  -> ab and cd cross: " << t2::segments_intersect(a, b, c, d) << "\n";
  // The same four signs for ab and the antipode of cd, a segment on the back side:
  const ExactPoint nc = t2::antipode(c), nd = t2::antipode(d);
  std::cout << "orient(a,b,~c) = " << sym(t2::orient(a, b, nc))
            << ", orient(a,b,~d) = " << sym(t2::orient(a, b, nd))
            << ", orient(~c,~d,a) = " << sym(t2::orient(nc, nd, a))
            << ", orient(~c,~d,b) = " << sym(t2::orient(nc, nd, b))
            << "  -> ab and ~c~d meet: " << t2::segments_intersect(a, b, nc, nd) << "\n";
  //< four-orientations
  std::cout << "fifth sign: orient(a,b,c) = " << sym(t2::orient(a, b, c)) << " vs -orient(c,d,a) = "
            << sym(-t2::orient(c, d, a)) << " (equal: same point);  orient(a,b,~c) = " << sym(t2::orient(a, b, nc))
            << " vs -orient(~c,~d,a) = " << sym(-t2::orient(nc, nd, a)) << " (different: antipodal points)\n\n";
}

// ---------------------------------------------------------------------------------------------
// 3. Signed area.

const ExactPolygon& example_polygon() {
  // An arrow-shaped polygon, counter-clockwise, with a reflex vertex and a straight vertex.
  static const ExactPolygon poly{P(0, 0), P(3, 0), P(6, 0), P(6, 4), P(3, 2), P(0, 4)};
  return poly;
}

void area() {
  std::cout << "== 3. Signed area\n";
  //> area-demo
  const ExactPolygon& poly = example_polygon();
  std::cout << "2 * area = " << t2::signed_area(poly).get_str()
            << ", orientation = " << sym(t2::orientation(poly)) << "\n";
  ExactPolygon reversed(poly.rbegin(), poly.rend()), back;
  for (const auto& p : poly) back.push_back(t2::antipode(p));
  std::cout << "reversed: " << t2::signed_area(reversed).get_str() << ", on the back side: "
            << t2::signed_area(back).get_str() << "\n";
  //< area-demo
  const t2::Polygon tiny{Point(1, 0.1, 0.1), Point(1, 0.2, 0.2), Point(1, 0.3, 0.3)};
  std::cout << "three rounded 'collinear' doubles (0.1,0.1) (0.2,0.2) (0.3,0.3): signed_area = "
            << t2::signed_area(tiny) << ", exact orientation = " << sym(t2::orientation(tiny)) << "\n";
  try {
    (void)t2::signed_area(ExactPolygon{P(0, 0), ExactPoint(0, 1, 0), P(0, 1)});
  } catch (const t2::Undefined& e) {
    std::cout << "a vertex on Omega: Undefined: " << e.what() << "\n";
  }
  std::cout << "\n";
}

// ---------------------------------------------------------------------------------------------
// 4. Point in polygon.

// The seed's Algorithm 2, literally: "esta_sobre" is t2::on_segment and "intercepta" is the
// closed-segment test. Undefined walks (q = ¬p0) are reported as 2.
int seed_algorithm2(const ExactPolygon& Pp, const ExactPoint& q) {
  //> seed-algorithm2
  const std::size_t n = Pp.size();
  const ExactPoint &p0 = Pp[0], &p1 = Pp[1], &pl = Pp[n - 1];
  if (q == t2::antipode(p0)) return 2;  // the seed does not say
  int s = t2::orient(q, p0, p1);
  const int t = t2::orient(pl, p0, p1);
  const int b = t2::orient(q, pl, p0);
  if (s * b == -1) {
    s = -t;
  } else if (s * b == 0) {
    if (s == 0)
      s = (int(t2::on_segment(p0, p1, q)) - 1) * t;
    else
      s = (int(t2::on_segment(pl, p0, q)) - 1) * t;
  }
  for (std::size_t i = 1; i + 1 < n; ++i)
    if (t2::segments_intersect(Pp[i], Pp[i + 1], p0, q)) s = -s;
  return s;
  //< seed-algorithm2
}

void point_in_polygon() {
  std::cout << "== 4. Point in polygon\n";
  const ExactPolygon& poly = example_polygon();
  //> pip-demo
  const ExactPoint queries[] = {P(1, 1), P(3, 3), P(5, 0),
                                P(8, 0), P(3, 2), t2::antipode(P(1, 1))};
  for (const ExactPoint& q : queries)
    std::cout << "q = " << str(q) << ": ray casting "
              << (q.w() > 0 ? sym(t2::locate_by_ray_casting(poly, q)) : "n/a")
              << ", locate " << sym(t2::locate(poly, q)) << "\n";
  //< pip-demo
  // Winding numbers of a self-intersecting polygon: the pentagram.
  //> winding-demo
  const ExactPolygon star{P(0, 10), P(-6, -8), P(10, 3), P(-10, 3), P(6, -8)};
  for (const ExactPoint& q : {P(0, 0), P(0, 5), P(20, 0)})
    std::cout << "pentagram, q = " << cart(q) << ": winding number "
              << t2::winding_number(star, q) << ", ray casting "
              << sym(t2::locate_by_ray_casting(star, q)) << "\n";
  //< winding-demo
  // The seed's algorithm, literally, against t2::locate on every point of a half-integer grid.
  int total = 0, wrong = 0, undefined = 0;
  std::string first;
  for (long x = -4; x <= 16; ++x)
    for (long y = -4; y <= 12; ++y) {
      const ExactPoint q(2, x, y);
      for (const ExactPoint& qq : {q, t2::antipode(q)}) {
        ++total;
        const int seed = seed_algorithm2(poly, qq);
        if (seed == 2) {
          ++undefined;
          continue;
        }
        if (seed != int(t2::locate(poly, qq))) {
          if (first.empty())
            first = str(qq) + " (seed " + std::to_string(seed) + ", locate " + sym(t2::locate(poly, qq)) + ")";
          ++wrong;
        }
      }
    }
  std::cout << "seed Algorithm 2 literally, on " << total << " grid points and antipodes: " << wrong
            << " wrong, " << undefined << " undefined (q = ~p0); first wrong: " << first << "\n";
  // A polygon of T²: the image of the example under a projective map that sends two vertices to
  // the back side and the query point (3, 3) to Omega.
  //> t2-polygon
  auto map = [](const ExactPoint& p) {  // [w, x, y] -> [3w - y, x, y]: a map with det 3 > 0
    return ExactPoint(t2::Integer(3 * p.w() - p.y()), p.x(), p.y());
  };
  ExactPolygon image;
  for (const auto& p : poly) image.push_back(map(p));
  for (const auto& p : image) std::cout << str(p) << " ";
  std::cout << "\n";
  for (const ExactPoint& q : {P(1, 1), P(3, 3), P(5, 1)})
    std::cout << "locate(image, map(" << cart(q)
              << ")) = " << sym(t2::locate(image, map(q)))
              << "   winding = " << t2::winding_number(image, map(q)) << "\n";
  //< t2-polygon
  std::cout << "\n";
}

// ---------------------------------------------------------------------------------------------
// 5. Ear clipping.

void ears() {
  std::cout << "== 5. Ear clipping\n";
  //> ear-demo
  const ExactPolygon& poly = example_polygon();
  t2::Rational sum = 0;
  for (const auto& t : t2::ear_clipping(poly)) {
    const ExactPolygon tri{poly[t[0]], poly[t[1]], poly[t[2]]};
    std::cout << "(" << t[0] << ", " << t[1] << ", " << t[2] << ") 2*area "
              << t2::signed_area(tri).get_str() << "\n";
    sum += t2::signed_area(tri);
  }
  std::cout << "sum " << sum.get_str() << " = 2*area of the polygon "
            << t2::signed_area(poly).get_str() << "\n";
  //< ear-demo
  //> ear-complement
  // A small square traversed clockwise: its positive side is everything outside the square.
  const ExactPolygon cw{P(0, 0), P(0, 1), P(1, 1), P(1, 0)};
  std::cout << "clockwise square, turn at each vertex:";
  for (std::size_t i = 0; i < cw.size(); ++i)
    std::cout << " " << sym(t2::orient(cw[(i + 3) % 4], cw[i], cw[(i + 1) % 4]));
  std::cout << " (every vertex reflex for the positive side)\n";
  //< ear-complement
  std::cout << "\n";
}

// ---------------------------------------------------------------------------------------------
// 6. Convexity in T².

//> hull-certificates
// The two certificates of the hemisphere theorem. A set lies in the open hemisphere of l
// when every point is strictly on the positive side of l; a set has no convex hull when
// some coefficients λ_i >= 0, not all zero, make the vector sum Σ λ_i a_i the zero
// vector.
bool in_open_hemisphere(const t2::ExactLine& l, const ExactPolygon& A) {
  for (const ExactPoint& a : A)
    if (t2::side(l, a) != t2::POSITIVE) return false;
  return true;
}
bool sums_to_zero(const std::vector<int>& lambda, const ExactPolygon& A) {
  t2::Integer w = 0, x = 0, y = 0;
  bool some = false;
  for (std::size_t i = 0; i < A.size(); ++i) {
    if (lambda[i] < 0) return false;
    some = some || lambda[i] > 0;
    w += lambda[i] * A[i].w();
    x += lambda[i] * A[i].x();
    y += lambda[i] * A[i].y();
  }
  return some && w == 0 && x == 0 && y == 0;
}
//< hull-certificates

void require(bool ok, const char* what) {
  if (!ok) throw std::logic_error(std::string("chapter 05 check failed: ") + what);
}

// The three sets of section 6: A has a hull (front, back and Ω points), B has none (the
// antipode of its back point is inside its front triangle), C lies on one line, in no open
// hemisphere although no two of its points are antipodal.
ExactPolygon set_A() { return {P(-2, -1), P(2, -1), ExactPoint(0, -1, 1), ExactPoint(-1, 1, 3)}; }
ExactPolygon set_B() { return {P(-2, -1), P(2, -1), P(0, 2), ExactPoint(-1, 0, 0)}; }

// The hull of a set in general position that lies in an open hemisphere, by its definition:
// a -> b is an edge when every other point is strictly to its left. O(n^3): enough for a figure.
std::vector<std::size_t> hull_order(const ExactPolygon& A) {
  std::vector<std::size_t> order;
  std::size_t i = 0, guard = 0;
  do {
    for (std::size_t j = 0; j < A.size(); ++j) {
      bool edge = i != j;
      for (std::size_t k = 0; k < A.size() && edge; ++k)
        if (k != i && k != j) edge = t2::orient(A[i], A[j], A[k]) == t2::POSITIVE;
      if (edge) {
        order.push_back(i);
        i = j;
        break;
      }
    }
    require(++guard <= A.size(), "hull edges form one cycle");
  } while (i != 0 || order.empty());
  return order;
}

void convexity() {
  std::cout << "== 6. Convexity in T2\n";
  auto list = [](const ExactPolygon& A) {
    std::string s;
    for (const auto& a : A) s += str(a) + " ";
    return s;
  };
  //> hull-demo
  const ExactPolygon A = set_A(), B = set_B();
  const ExactPolygon C{ExactPoint(2, 0, 0), ExactPoint(-1, 1, 0), ExactPoint(-1, -1, 0)};
  const t2::ExactLine l(2, 0, 1);  // 2w + y > 0
  std::cout << "A = " << list(A) << ": all on the positive side of " << t2::to_string(l)
            << ": " << in_open_hemisphere(l, A) << "\n";
  std::cout << "B = " << list(B) << ": 1 b0 + 1 b1 + 1 b2 + 3 b3 = [0, 0, 0]: "
            << sums_to_zero({1, 1, 1, 3}, B) << "\n";
  std::cout << "C = " << list(C) << ": 1 c0 + 1 c1 + 1 c2 = [0, 0, 0]: "
            << sums_to_zero({1, 1, 1}, C) << "\n";
  //< hull-demo
  bool antipodal = false;
  for (const auto* S : {&A, &B, &C})
    for (const auto& p : *S)
      for (const auto& q : *S) antipodal = antipodal || p == t2::antipode(q);
  std::cout << "antipodal pairs in A, B, C: " << antipodal << "; side(<0, 0, 1>, c) for c in C: "
            << sym(t2::side(t2::ExactLine(0, 0, 1), C[0])) << sym(t2::side(t2::ExactLine(0, 0, 1), C[1]))
            << sym(t2::side(t2::ExactLine(0, 0, 1), C[2])) << "\n";
  require(in_open_hemisphere(l, A) && sums_to_zero({1, 1, 1, 3}, B) && sums_to_zero({1, 1, 1}, C) && !antipodal,
          "hemisphere certificates");
  std::cout << "hull of A, counter-clockwise:";
  for (const std::size_t i : hull_order(A)) std::cout << " a" << i;
  std::cout << "\n\n";
}

// ---------------------------------------------------------------------------------------------
// Figures.

void figures(const std::filesystem::path& dir) {
  dr::PlaneView plane;
  plane.half_width = 5;
  plane.cx = 3;
  plane.cy = 2;
  int written = 0, count = 0;
  auto save = [&](const dr::Figure& f, const std::string& name, const dr::PlaneView& pv,
                  const dr::SphereView& sv = dr::SphereView()) {
    written += dr::save(f, pv, dir / (name + "-plane.svg"));
    written += dr::save(f, sv, dir / (name + "-sphere.svg"));
    count += 2;
  };
  const ExactPolygon& poly = example_polygon();
  {  // Convexity: A has a hull inside the open hemisphere of l; B has none.
    dr::Figure f;
    const ExactPolygon A = set_A();
    ExactPolygon hull;
    for (const std::size_t i : hull_order(A)) hull.push_back(A[i]);
    f.add(t2::ExactLine(2, 0, 1), dr::Style().color(pal::grey).dash({5, 3}).label("l"));
    f.add(hull, dr::Style().fill(pal::green).fill_opacity(0.2).color(pal::green).width(1.6));
    for (std::size_t i = 0; i < A.size(); ++i) f.add(A[i], dr::Style().label("a" + std::to_string(i)));
    dr::PlaneView pv;
    pv.cy = -1;
    dr::SphereView side_on;  // l's great circle nearly edge-on, its positive side above it
    side_on.lat = 20;
    side_on.lon = 10;
    save(f, "hull-exists", pv, side_on);
    dr::Figure g;
    const ExactPolygon B = set_B();
    g.add(ExactPolygon{B[0], B[1], B[2]}, dr::Style().fill(pal::blue).fill_opacity(0.15).width(1.6));
    for (std::size_t i = 0; i < 3; ++i) g.segment(B[i], B[3], dr::Style().color(pal::red).dash({4, 3}));
    for (std::size_t i = 0; i < B.size(); ++i) g.add(B[i], dr::Style().label("b" + std::to_string(i)));
    dr::SphereView from_minus_y;  // the front triangle on top, the back point b3 below
    from_minus_y.lat = 30;
    from_minus_y.lon = -100;
    save(g, "hull-none", pv, from_minus_y);
  }
  {  // Point location: inside green, outside red, boundary black.
    dr::Figure f;
    f.add(poly, dr::Style().fill(pal::blue).fill_opacity(0.15).width(1.6));
    for (long x = -2; x <= 16; x += 2)
      for (long y = -2; y <= 10; y += 2) {
        const ExactPoint q(2, x, y);
        const Sign s = t2::locate(poly, q);
        f.add(q, dr::Style().size(2.5).color(s > 0 ? pal::green : (s < 0 ? pal::red : pal::black)));
      }
    save(f, "locate", plane);
  }
  {  // A polygon of T²: the image under [w,x,y] -> [3w - y, x, y]; two vertices on the back side.
    dr::Figure f;
    ExactPolygon image;
    for (const auto& p : poly) image.push_back(ExactPoint(t2::Integer(3 * p.w() - p.y()), p.x(), p.y()));
    f.add(image, dr::Style().fill(pal::blue).fill_opacity(0.15).width(1.6));
    for (std::size_t i = 0; i < image.size(); ++i)
      f.add(image[i], dr::Style().label("p" + std::to_string(i)));
    dr::PlaneView wide;  // wide enough for the back vertices p3 = (-6, -4) and p5 = (0, -4)
    wide.half_width = 8;
    wide.cx = -1;
    wide.cy = -1;
    dr::SphereView facing;  // towards the mean of the vertices' unit vectors, (3.2, 2.1, 2.1)
    facing.lat = 28;
    facing.lon = 32;
    save(f, "t2-polygon", wide, facing);
  }
  {  // Ear clipping.
    dr::Figure f;
    for (const auto& t : t2::ear_clipping(poly))
      f.add(ExactPolygon{poly[t[0]], poly[t[1]], poly[t[2]]},
            dr::Style().fill(pal::orange).fill_opacity(0.2).color(pal::light_grey));
    f.add(poly, dr::Style().width(2));
    for (std::size_t i = 0; i < poly.size(); ++i) f.add(poly[i], dr::Style().label(std::to_string(i)));
    save(f, "ears", plane);
  }
  {  // The fifth orientation: ab crosses cd, but not ~c~d although the four signs agree.
    dr::Figure f;
    const ExactPoint a = P(-2, 0), b = P(2, 0), c = P(0, -2), d = P(0, 2);
    f.segment(a, b, dr::Style().width(2).color(pal::blue));
    f.segment(c, d, dr::Style().width(2).color(pal::green));
    f.segment(t2::antipode(c), t2::antipode(d), dr::Style().width(2).color(pal::red));
    f.add(a, dr::Style().label("a"));
    f.add(b, dr::Style().label("b"));
    f.add(c, dr::Style().label("c"));
    f.add(d, dr::Style().label("d"));
    f.add(t2::antipode(c), dr::Style().label("~c").color(pal::red));
    f.add(t2::antipode(d), dr::Style().label("~d").color(pal::red));
    dr::PlaneView centred;
    centred.half_width = 3;
    save(f, "fifth", centred);
  }
  {  // Closest points.
    dr::Figure f;
    const ExactPoint a = P(0, 0), b = P(4, 2);
    f.segment(a, b, dr::Style().width(2));
    for (const ExactPoint& q : {P(1, 3), P(-2, 1), ExactPoint(2, 10, 6)}) {
      const ExactPoint c = t2::closest_point_on_segment(a, b, q);
      f.segment(q, c, dr::Style().color(pal::light_grey).dash({4, 3}));
      f.add(q, dr::Style().color(pal::blue));
      f.add(c, dr::Style().color(pal::red));
    }
    save(f, "closest", plane);
  }
  std::cerr << "figures: " << count << " in " << dir.string() << " (" << written << " changed)\n";
}

}  // namespace

int main(int argc, char** argv) {
  const std::filesystem::path dir = dr::figures_dir(argc, argv, T2_FIGURES_DIR);
  std::cout << std::boolalpha;
  closest_point();
  intersection();
  area();
  point_in_polygon();
  ears();
  convexity();
  figures(dir);
}
