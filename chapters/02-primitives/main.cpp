// Chapter 02, primitives: lines, segments (front, back, crossing), rays, vectors and
// directions, triangles, iso-rectangles, bounding boxes, circles, affine and projective maps.
//
// Prints a worked example of every primitive and of each of its undefined cases (the message
// of t2::Undefined names the broken rule), checks the library against small independent
// oracles, and writes the chapter's figures, in the planar and the spherical model, into
// --figures DIR. Deterministic: nothing printed depends on the figures directory.
#include <t2/t2.hpp>

#include <cmath>
#include <filesystem>
#include <functional>
#include <iostream>
#include <string>
#include <vector>

namespace {

using t2::ExactPoint;
using t2::Integer;
using t2::Sign;
namespace dr = t2::draw;
namespace pal = t2::draw::palette;
using P = ExactPoint;
using T1 = t2::ExactT1;

std::string str(const P& p) { return t2::to_string(p); }
const char* sym(Sign s) { return t2::to_symbol(s); }

// Runs f; prints "what -> result" or "what -> undefined: <rule>".
void attempt(const std::string& what, const std::function<std::string()>& f) {
  try {
    const std::string result = f();
    std::cout << "  " << what << " -> " << result << "\n";
  } catch (const t2::Undefined& e) {
    std::cout << "  " << what << " -> undefined: " << e.what() << "\n";
  }
}

// ---------------------------------------------------------------------------------------------
// 1. Lines.

void lines() {
  std::cout << "== 1. Lines\n";
  //> line-demo
  const P p = P::cartesian(0, 0), q = P::cartesian(2, 1);
  const t2::ExactLine l =
      t2::join(p, q);  // oriented: positive side on the left of p -> q
  const t2::ExactLine m = t2::join(q, p);  // the same points, the opposite orientation
  const t2::ExactLine o =
      t2::omega<Integer>();  // the line at infinity, front side positive
  //< line-demo
  std::cout << "  join(p, q) = " << t2::to_string(l) << ", join(q, p) = " << t2::to_string(m)
            << ", opposite(join(p, q)) == join(q, p): " << (t2::opposite(l) == m) << "\n";
  std::cout << "  Omega = " << t2::to_string(o) << ": side(Omega, p) = " << sym(t2::side(o, p))
            << ", side(Omega, antipode(p)) = " << sym(t2::side(o, t2::antipode(p))) << "\n";
  attempt("join(p, p)", [&] { return t2::to_string(t2::join(p, p)); });
  attempt("join(p, antipode(p))", [&] { return t2::to_string(t2::join(p, t2::antipode(p))); });
  std::cout << "\n";
}

// ---------------------------------------------------------------------------------------------
// 2. Segments.

void segments() {
  std::cout << "== 2. Segments\n";
  //> segment-cases
  const P a = P::cartesian(-2, -1), b = P::cartesian(1, 2);  // two front points
  const P c(-1, 1, -1), d(-2, -4, -2);  // two back points: (-1, 1), (2, 1)
  const t2::ExactSegment front(a, b), back(c, d), crossing(a, d);
  //< segment-cases
  for (const auto* s : {&front, &back, &crossing})
    std::cout << "  " << t2::to_string(*s) << ": kind " << t2::to_string(t2::kind(*s)) << "\n";
  //> segment-crossing
  const P at_omega = t2::point_at_infinity(crossing);         // |w_d| a + |w_a| d
  const auto pieces = t2::planar_pieces(crossing);  // two half-rays in the planar model
  //< segment-crossing
  std::cout << "  point_at_infinity(a d) = " << str(at_omega) << "; planar pieces: ";
  for (std::size_t i = 0; i < pieces.size(); ++i)
    std::cout << (i ? " " : "") << t2::to_string(pieces[i]) << " (" << t2::to_string(t2::kind(pieces[i])) << ")";
  std::cout << "\n";
  // Oracle: the crossing point is a non-negative combination of a and d with w = 0.
  std::cout << "  on_segment(a, d, point_at_infinity) = " << t2::on_segment(a, d, at_omega)
            << ", on_segment(a, d, its antipode) = " << t2::on_segment(a, d, t2::antipode(at_omega)) << "\n";
  // Counting oracle: front-front segments never leave the front side (w = αw_a + βw_b > 0).
  int pairs = 0, kinds_ok = 0;
  for (int w1 : {-1, 1})
    for (int x1 = -2; x1 <= 2; ++x1)
      for (int w2 : {-1, 0, 1})
        for (int x2 = -2; x2 <= 2; ++x2) {
          const P u(w1, x1, 1), v(w2, x2, -1);
          if (u == t2::antipode(v)) continue;
          ++pairs;
          const t2::SegmentKind k = t2::kind(t2::ExactSegment(u, v));
          const bool want = w2 == 0 ? (k == (w1 > 0 ? t2::SegmentKind::front_ray : t2::SegmentKind::back_ray))
                                    : w1 == w2 ? (k == (w1 > 0 ? t2::SegmentKind::front : t2::SegmentKind::back))
                                               : k == t2::SegmentKind::crossing;
          kinds_ok += want;
        }
  std::cout << "  kind agrees with the signs of the weights on " << kinds_ok << " of " << pairs << " segments\n";
  attempt("segment(a, a)", [&] {
    const t2::ExactSegment s(a, a);
    return std::string("degenerate one-point segment: ") + (s.is_degenerate() ? "yes" : "no");
  });
  attempt("segment(a, antipode(a))", [&] { return t2::to_string(t2::ExactSegment(a, t2::antipode(a))); });
  std::cout << "\n";
}

// ---------------------------------------------------------------------------------------------
// 3. Rays, vectors and directions.

void rays_vectors_directions() {
  std::cout << "== 3. Rays, vectors and directions\n";
  //> vector-demo
  const P p = P::cartesian(1, 1), q = P::cartesian(4, 5);
  const P r(-1, -3, -1);                          // a back point, Cartesian (3, 1)
  const t2::ExactVector u = t2::vector(p, q);     // an ordinary vector: (3, 4)
  const t2::ExactVector v = t2::vector(p, r);     // front to back: w < 0, "beyond infinity"
  const t2::ExactRay ray(p, t2::ExactDirection(Integer(3), Integer(4)));
  //< vector-demo
  std::cout << "  vector(p, q) = " << t2::to_string(u) << ", vector(p, r) = " << t2::to_string(v) << "\n";
  std::cout << "  direction(p, q) = " << t2::to_string(t2::direction(p, q)) << ", direction(p, r) = "
            << t2::to_string(t2::direction(p, r)) << ", direction(q, p) = " << t2::to_string(t2::direction(q, p))
            << "\n";
  // The translation by vector(p, x) takes p exactly to x, whatever the side of x.
  for (const P& x : {q, r}) {
    const auto moved = t2::transform(t2::ExactAffine::translation(t2::vector(p, x)), p);
    std::cout << "  translation(vector(p, " << str(x) << ")) maps p to " << str(moved) << " == x: " << (moved == x)
              << "\n";
  }
  std::cout << "  " << t2::to_string(ray) << ": contains q " << t2::contains(ray, q) << ", contains r "
            << t2::contains(ray, r) << ", contains [0, 3, 4] " << t2::contains(ray, P(0, 3, 4)) << "\n";
  std::cout << "  ray through p and r: " << t2::to_string(t2::ExactRay::through(p, r)) << "\n";
  attempt("ray([0, 1, 0], direction(3, 4))",
          [&] { return t2::to_string(t2::ExactRay(P(0, 1, 0), t2::ExactDirection(Integer(3), Integer(4)))); });
  attempt("vector with tip antipode(O)", [&] { return t2::to_string(t2::ExactVector(-1, 0, 0)); });
  attempt("vector(p, antipode(p))", [&] { return t2::to_string(t2::vector(p, t2::antipode(p))); });
  attempt("vector([0, 1, 0], q)", [&] { return t2::to_string(t2::vector(P(0, 1, 0), q)); });
  attempt("direction(0, 0)", [&] { return t2::to_string(t2::ExactDirection(Integer(0), Integer(0))); });
  attempt("direction([0, 1, 0], [0, 0, 1])", [&] { return t2::to_string(t2::direction(P(0, 1, 0), P(0, 0, 1))); });
  attempt("direction(p, antipode(p))", [&] { return t2::to_string(t2::direction(p, t2::antipode(p))); });
  attempt("direction(Omega)", [&] { return t2::to_string(t2::direction(t2::omega<Integer>())); });
  std::cout << "\n";
}

// ---------------------------------------------------------------------------------------------
// 4. Triangles.

void triangles() {
  std::cout << "== 4. Triangles\n";
  //> triangle-demo
  const P a = P::cartesian(0, 0), b = P::cartesian(3, 0),
          c(-1, -1, -2);  // c: back point (1, 2)
  const t2::ExactTriangle t(a, b, c);
  const P inside =
      P::cartesian(1, -1);  // front, below the x axis: inside, via Omega and the back
  //< triangle-demo
  std::cout << "  " << t2::to_string(t) << ": orientation " << sym(t2::orientation(t)) << "\n";
  for (const P& x : {inside, t2::antipode(inside), P::cartesian(1, 1), P(0, 1, 2), P(0, -1, -2)}) {
    const auto bs = t2::bounded_side(t, x);
    std::cout << "  bounded_side(t, " << str(x) << ") = "
              << (bs == t2::BoundedSide::inside ? "inside" : bs == t2::BoundedSide::boundary ? "boundary" : "outside")
              << "\n";
  }
  // Oracle: x is in the cone of a, b, c iff x = αa + βb + γc with α, β, γ >= 0, i.e. (Cramer)
  // the three determinants Δ(x,b,c), Δ(a,x,c), Δ(a,b,x) have the sign of Δ(a,b,c) or are 0.
  int points = 0, agree = 0;
  for (int w = -1; w <= 1; ++w)
    for (int x = -3; x <= 3; ++x)
      for (int y = -3; y <= 3; ++y) {
        if (w == 0 && x == 0 && y == 0) continue;
        const P s(w, x, y);
        const Sign o = t2::orient(a, b, c);
        const bool cone = t2::orient(s, b, c) * o >= 0 && t2::orient(a, s, c) * o >= 0 && t2::orient(a, b, s) * o >= 0;
        ++points;
        agree += cone == t2::contains(t, s);
      }
  std::cout << "  contains agrees with the cone test (Cramer signs) on " << agree << " of " << points << " points\n";
  attempt("triangle(a, b, antipode(a))", [&] { return t2::to_string(t2::ExactTriangle(a, b, t2::antipode(a))); });
  attempt("flat triangle(a, (1,0), b)",
          [&] { return t2::to_string(t2::ExactTriangle(a, P::cartesian(1, 0), b)) + " (allowed: it is segment ab)"; });
  attempt("flat triangle(a, b, [-1, -1, 0])",
          [&] { return t2::to_string(t2::ExactTriangle(a, b, P(-1, -1, 0))); });
  std::cout << "\n";
}

// ---------------------------------------------------------------------------------------------
// 5. Iso-rectangles and bounding boxes.

void rectangles_and_boxes() {
  std::cout << "== 5. Iso-rectangles and bounding boxes\n";
  //> isorect-demo
  const P a = P::cartesian(-1, 2);
  const t2::ExactIsoRect finite(a, T1::finite(Integer(3)), T1::finite(Integer(-1)));
  const t2::ExactIsoRect quadrant(a, T1::plus_infinity(),
                                  T1::plus_infinity());  // both extents +inf
  //< isorect-demo
  std::cout << "  finite:   " << t2::to_string(finite) << "\n  quadrant: " << t2::to_string(quadrant) << "\n";
  //> seed-corner
  const P c = quadrant.corner(2);                            // the corrected corner: b + d
  const P seed_c(Integer(0), a.x(), a.y());                  // the seed's [0, x_a, y_a]
  const P b = quadrant.corner(1), d = quadrant.corner(3);    // [0, 1, 0] and [0, 0, 1]
  //< seed-corner
  std::cout << "  corner c = " << str(c) << " on arc b d: " << t2::on_segment(b, d, c) << "; seed's c = "
            << str(seed_c) << " on arc b d: " << t2::on_segment(b, d, seed_c) << "\n";
  attempt("the seed's c = [0, x_a, y_a] for a at the origin", [] { return str(P(0, 0, 0)); });
  attempt("iso_rect(a, dx = [-1, 1], dy = 1)",
          [&] { return t2::to_string(t2::ExactIsoRect(a, T1(Integer(-1), Integer(1)), T1::finite(Integer(1)))); });
  attempt("iso_rect([0, 1, 1], 1, 1)",
          [&] { return t2::to_string(t2::ExactIsoRect(P(0, 1, 1), T1::finite(Integer(1)), T1::finite(Integer(1)))); });
  attempt("iso_rect(a, [0, 1, 0])", [&] { return t2::to_string(t2::iso_rect(a, P(0, 1, 0))); });
  attempt("iso_rect(a, antipode((1, 1)))",
          [&] { return t2::to_string(t2::iso_rect(a, t2::antipode(P::cartesian(1, 1)))); });

  //> bbox-demo
  const t2::ExactBBox b1(P::cartesian(0, 0), T1::finite(Integer(2)),
                         T1::finite(Integer(1)));
  const t2::ExactBBox b2(P::cartesian(1, 3), T1::plus_infinity(),
                         T1::finite(Integer(1)));  // x to +inf
  const t2::ExactBBox b3(P::cartesian(5, 0), T1::minus_infinity(),
                         T1::finite(Integer(1)));  // x to -inf
  const t2::ExactBBox back(P(-1, 0, 0), T1::minus_infinity(),
                           T1::finite(Integer(1)));  // back side
  //< bbox-demo
  std::cout << "  b1 = " << t2::to_string(b1) << "\n  b2 = " << t2::to_string(b2) << "\n  b3 = " << t2::to_string(b3)
            << "\n  back = " << t2::to_string(back) << "\n";
  attempt("b1 + b2", [&] { return t2::to_string(b1 + b2); });
  attempt("b1 + b3", [&] { return t2::to_string(b1 + b3); });
  attempt("b2 + b3", [&] { return t2::to_string(b2 + b3); });
  attempt("bbox((0,0), back (1,1))", [] { return t2::to_string(t2::bbox({P::cartesian(0, 0), P(-1, -1, -1)})); });
  attempt("bbox((0,0), [0, 1, 0], [0, -1, 1])",
          [] { return t2::to_string(t2::bbox({P::cartesian(0, 0), P(0, 1, 0), P(0, -1, 1)})); });
  attempt("b1 + back", [&] { return t2::to_string(b1 + back); });
  auto meet = [](const t2::ExactBBox& x, const t2::ExactBBox& y) -> std::string {
    const auto r = t2::intersection(x, y);
    if (const auto* box = std::get_if<t2::ExactBBox>(&r)) return t2::to_string(*box);
    if (const auto* s = std::get_if<t2::ExactSegment>(&r)) return "on Omega: " + t2::to_string(*s);
    return "empty";
  };
  std::cout << "  b2 & b3 = " << meet(b2, b3) << "\n  b1 & b2 = " << meet(b1, b2) << "\n  b3 & back = " << meet(b3, back)
            << "\n  b2 & back = " << meet(b2, back) << "\n";
  std::cout << "\n";
}

// ---------------------------------------------------------------------------------------------
// 6. Circles.

void circles() {
  std::cout << "== 6. Circles\n";
  //> circle-demo
  const P o = P::cartesian(0, 0);
  const t2::ExactCircle finite(o, P::cartesian(3, 4));      // radius 5
  const t2::ExactCircle hemisphere(o, P(0, 1, 0));          // boundary Omega itself
  const t2::ExactCircle line(P(0, 0, 1), P::cartesian(2, 0)); // centre at infinity: a line
  const t2::ExactCircle beyond(o, P(-1, -3, -4));           // boundary on the back side
  //< circle-demo
  for (const auto* c : {&finite, &hemisphere, &line, &beyond})
    std::cout << "  " << t2::to_string(*c) << ": radius " << t2::to_string(t2::radius_kind(*c)) << "\n";
  const auto through = t2::circle_through(P::cartesian(1, 0), P::cartesian(0, 1), P::cartesian(-1, 0));
  std::cout << "  circle_through((1,0), (0,1), (-1,0)) = " << t2::to_string(through) << "\n";
  const auto collinear = t2::circle_through(P::cartesian(0, 0), P::cartesian(1, 1), P(-1, -2, -2));
  std::cout << "  circle_through((0,0), (1,1), back (2,2)) = " << t2::to_string(collinear) << ", radius "
            << t2::to_string(t2::radius_kind(collinear)) << "\n";
  std::cout << "  circle_from_diameter((0,0), (4,2)) = "
            << t2::to_string(t2::circle_from_diameter(P::cartesian(0, 0), P::cartesian(4, 2))) << "\n";
  attempt("circle([0, 1, 0], [0, 0, 1])", [] { return t2::to_string(t2::ExactCircle(P(0, 1, 0), P(0, 0, 1))); });
  attempt("circle_from_diameter((0,0), back (4,2))",
          [] { return t2::to_string(t2::circle_from_diameter(P::cartesian(0, 0), P(-1, -4, -2))); });
  attempt("circle_through((1,0), (0,1), back (-1,0))",
          [] { return t2::to_string(t2::circle_through(P::cartesian(1, 0), P::cartesian(0, 1), P(-1, 1, 0))); });
  attempt("circle_through((1,0), (0,1), [0, 1, 1])",
          [] { return t2::to_string(t2::circle_through(P::cartesian(1, 0), P::cartesian(0, 1), P(0, 1, 1))); });
  // The seed's exception for a diameter with ends on different sides never holds: search for one.
  int tried = 0, defined = 0;
  for (int x1 = -3; x1 <= 3; ++x1)
    for (int y1 = -3; y1 <= 3; ++y1)
      for (int x2 = -3; x2 <= 3; ++x2)
        for (int y2 = -3; y2 <= 3; ++y2) {
          const P p = P::cartesian(x1, y1), q(-1, -x2, -y2);
          if (p == t2::antipode(q)) continue;
          ++tried;
          try {
            (void)t2::circle_from_diameter(p, q);
            ++defined;
          } catch (const t2::Undefined&) {
          }
        }
  std::cout << "  diameters with ends on different sides: " << defined << " of " << tried << " define a circle\n\n";
}

// ---------------------------------------------------------------------------------------------
// 7. Affine and projective maps.

void maps() {
  std::cout << "== 7. Affine and projective maps\n";
  //> map-demo
  const auto rot =
      t2::ExactAffine::rotation(Integer(3), Integer(4), Integer(5));  // sin 3/5, cos 4/5
  const auto mirror = t2::ExactAffine({{{1, 0, 0}, {0, 1, 0}, {0, 0, -1}}});      // y -> -y
  const auto flip = t2::ExactAffine::scaling(Integer(1), Integer(-1));           // den < 0
  const auto persp = t2::ExactAffine({{{1, 1, 0}, {0, 1, 0}, {0, 0, 1}}});  // w' = w + x
  //< map-demo
  const P p = P::cartesian(5, 0), q = P::cartesian(0, 5), r = P::cartesian(-5, 0);
  for (const auto* m : {&rot, &mirror, &flip, &persp}) {
    const P mp = t2::transform(*m, p), mq = t2::transform(*m, q), mr = t2::transform(*m, r);
    std::cout << "  " << t2::to_string(*m) << ": affine " << m->is_affine() << ", det " << sym(m->determinant_sign())
              << ", p -> " << str(mp) << ", orient " << sym(t2::orient(p, q, r)) << " -> " << sym(t2::orient(mp, mq, mr))
              << "\n";
  }
  // Sides are kept: side(M l, M s) = side(l, s), for every map and a grid of points.
  const t2::ExactLine l = t2::join(p, q);
  int checks = 0, kept = 0;
  for (const auto* m : {&rot, &mirror, &flip, &persp}) {
    const t2::ExactLine ml = t2::transform(*m, l);
    for (int w = -1; w <= 1; ++w)
      for (int x = -3; x <= 3; ++x)
        for (int y = -3; y <= 3; ++y) {
          if (w == 0 && x == 0 && y == 0) continue;
          const P s(w, x, y);
          ++checks;
          kept += t2::side(ml, t2::transform(*m, s)) == t2::side(l, s);
        }
  }
  std::cout << "  side(transform(M, l), M s) == side(l, s) on " << kept << " of " << checks << " cases\n";
  std::cout << "  transform(persp, Omega) = " << t2::to_string(t2::transform(persp, t2::omega<Integer>())) << "\n";
  const t2::ExactRay ray(P::cartesian(0, 0), t2::ExactDirection(Integer(1), Integer(0)));
  attempt("transform(persp, ray)", [&] { return t2::to_string(t2::transform(persp, ray)); });
  const auto shear = t2::ExactAffine({{{1, 0, 0}, {0, 1, 1}, {0, 0, 1}}});
  attempt("transform(shear, circle)",
          [&] { return t2::to_string(t2::transform(shear, t2::ExactCircle(P::cartesian(0, 0), p))); });
  attempt("transform(rot, iso_rect)", [&] {
    return t2::to_string(t2::transform(rot, t2::ExactIsoRect(p, T1::finite(Integer(1)), T1::finite(Integer(1)))));
  });
  attempt("singular matrix", [] { return t2::to_string(t2::ExactAffine({{{1, 0, 0}, {0, 1, 1}, {0, 1, 1}}})); });
  std::cout << "\n";
}

// ---------------------------------------------------------------------------------------------
// Figures.

void figures(const std::filesystem::path& dir) {
  dr::PlaneView plane;
  plane.half_width = 4;
  dr::SphereView sphere;
  int written = 0;
  {  // The three segment cases of the planar model.
    const P a = P::cartesian(-2, -1), b = P::cartesian(1, 2), c(-1, 1, -1), d(-2, -4, -2);
    dr::Figure f;
    f.segment(a, b, dr::Style().color(pal::blue).width(2));
    f.segment(c, d, dr::Style().color(pal::green).width(2));
    f.segment(a, d, dr::Style().color(pal::red).width(2));
    f.add(a, dr::Style().label("a").label_angle(135));
    f.add(b, dr::Style().label("b"));
    f.add(c, dr::Style().label("c").label_angle(-135));
    f.add(d, dr::Style().label("d").label_angle(-45));
    f.add(t2::point_at_infinity(t2::ExactSegment(a, d)), dr::Style().color(pal::red).label("ad \u2229 \u03a9"));
    written += dr::save(f, plane, dir / "segments-plane.svg");
    written += dr::save(f, sphere, dir / "segments-sphere.svg");
  }
  {  // A triangle with a back vertex: it crosses Omega.
    const P a = P::cartesian(0, 0), b = P::cartesian(3, 0), c(-1, -1, -2);
    dr::Figure f;
    f.add(std::vector<P>{a, b, c}, dr::Style().color(pal::blue).fill(pal::shade));
    f.add(a, dr::Style().label("a").label_angle(-135));
    f.add(b, dr::Style().label("b").label_angle(-45));
    f.add(c, dr::Style().label("c"));
    f.add(P::cartesian(1, -1), dr::Style().color(pal::green).label("s").label_angle(-90));
    written += dr::save(f, plane, dir / "triangle-plane.svg");
    written += dr::save(f, sphere, dir / "triangle-sphere.svg");
  }
  {  // The quadrant a + [0, +inf] x [0, +inf] and its corners b, c, d on Omega.
    const P a = P::cartesian(-1, 2);
    const t2::ExactIsoRect r(a, T1::plus_infinity(), T1::plus_infinity());
    std::vector<P> v;
    for (int i = 0; i < 4; ++i) v.push_back(r.corner(i));
    dr::Figure f;
    f.add(v, dr::Style().color(pal::blue).fill(pal::shade));
    const char* names[4] = {"a", "b", "c", "d"};
    for (int i = 0; i < 4; ++i) f.add(v[i], dr::Style().label(names[i]).label_angle(i == 0 ? -135 : 45));
    f.add(P(0, a.x(), a.y()), dr::Style().color(pal::red).marker(dr::Marker::cross).size(6).label("seed's c"));
    written += dr::save(f, plane, dir / "quadrant-plane.svg");
    dr::SphereView facing = sphere;  // look from the quadrant's side of the sphere
    facing.lon = 60;
    written += dr::save(f, facing, dir / "quadrant-sphere.svg");
  }
  {  // The radius kinds: finite, beyond infinity (same spot, other side), infinite (a line).
    const P c = P::cartesian(1, 1);
    const t2::ExactCircle finite(c, P::cartesian(3, 1));          // radius 2
    const t2::ExactCircle beyond(c, P(-1, -4, -1));               // back (4, 1): 3 from c
    const t2::ExactCircle line(P(0, 1, 1), P::cartesian(-2, 0));  // centre at infinity
    // Label directions, one set per model, chosen so that no two labels overlap.
    auto circles = [&](bool planar) {
      dr::Figure f;
      f.add(finite, dr::Style().color(pal::blue).width(2).fill(pal::shade).arrow().label(
                        "finite"));
      f.add(beyond, dr::Style()
                        .color(pal::red)
                        .width(2)
                        .arrow()
                        .label("beyond infinity")
                        .label_angle(planar ? -20 : -100));
      f.add(line, dr::Style()
                      .color(pal::green)
                      .width(2)
                      .arrow()
                      .label("infinite")
                      .label_angle(planar ? -45 : 170));
      f.add(c, dr::Style().label("c").label_angle(-90));
      f.add(line.center(), dr::Style()
                               .color(pal::green)
                               .label("centre of the line")
                               .label_angle(planar ? 200 : -120));
      return f;
    };
    dr::PlaneView wide = plane;
    wide.half_width = 5;
    written += dr::save(circles(true), wide, dir / "circles-plane.svg");
    // c (at longitude 45) in view, ¬c and the back circle below.
    dr::SphereView view = sphere;
    view.lat = 20;
    view.lon = -5;
    written += dr::save(circles(false), view, dir / "circles-sphere.svg");
  }
  std::cout << "figures: 8 (segments, triangle, quadrant, circles; plane and sphere)\n";
  std::cerr << written << " figure file(s) rewritten\n";  // depends on the directory: not stdout
}

}  // namespace

int main(int argc, char** argv) {
  const std::filesystem::path dir = dr::figures_dir(argc, argv, T2_FIGURES_DIR);
  std::cout << std::boolalpha;
  lines();
  segments();
  rays_vectors_directions();
  triangles();
  rectangles_and_boxes();
  circles();
  maps();
  figures(dir);
}
