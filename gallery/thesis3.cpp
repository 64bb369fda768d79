// Gallery, part 1: the figures 3.1-3.12 of seed 000 (chapter 3 of the thesis: the models of
// T1 and T2, orientation, lines, segments, the sides of a line).
#include "gallery.hpp"

#include <functional>
#include <numbers>

namespace gallery {
namespace {

void fig_3_1() {  // T1 as a circle
  dr::Figure f;
  f.add(t2::T1(1, 0), lab(pal::blue, "[1, 0]", -40));
  f.add(t2::T1(1, 1), lab(pal::blue, "[1, 1]", 30));
  f.add(t2::T1(-1, -1), lab(pal::red, "¬[1, 1] = [−1, −1]", 210));
  f.add(t2::T1(-1, 0.5), lab(pal::red, "[−1, 0.5]", 170));
  dr::T1View v;
  dr::save(f, v, out_dir() / "fig-3-1-t1-circle.svg");
}

void fig_3_2() {  // T1 as two copies of the line
  dr::Figure f;
  f.add(t2::T1(1, 1), lab(pal::blue, "[1, 1]", 90));
  f.add(t2::T1(1, -2), lab(pal::blue, "[1, −2]", 90));
  f.add(t2::T1(-1, -1), lab(pal::red, "[−1, −1]", -90));
  f.add(t2::T1(-1, 2.5), lab(pal::red, "[−1, 2.5]", -90));
  dr::T1View v;
  v.model = dr::T1Model::lines;
  dr::save(f, v, out_dir() / "fig-3-2-t1-lines.svg");
}

dr::Figure models_scene() {
  dr::Figure f;
  const Point p(1, 1.5, 1), q(-1, 2, -1.5), r(0, -1, 1);
  f.add(p, lab(pal::blue, "p = [1, 1.5, 1]", 45));
  f.add(t2::antipode(p), lab(pal::red, "¬p", -135));
  f.add(q, lab(pal::red, "q = [−1, 2, −1.5]", -45));
  f.add(r, lab(pal::green, "r = [0, −1, 1]", 135));
  f.add(Point(1, 0, 0), lab(pal::black, "o = [1, 0, 0]", -60).marker(dr::Marker::square));
  f.add(Point(-1, 0, 0), lab(pal::dark_grey, "¬o", 120).marker(dr::Marker::square));
  return f;
}

void fig_3_3() { dr::save(models_scene(), plane(3), out_dir() / "fig-3-3-planar-model.svg"); }
void fig_3_4() {
  dr::SphereView v = sphere();
  v.graticule = true;
  dr::save(models_scene(), v, out_dir() / "fig-3-4-spherical-model.svg");
}

void fig_3_5() {  // orientation: u runs from q to r, the segment pu turns about p
  dr::Figure f;
  const Point p(1, -2, -1), q(1, 2, -1.5), r(1, 1, 2);
  f.segment(q, r, st(pal::blue).width(2).arrow());
  for (double t : {0.2, 0.5, 0.8}) {
    const Point u(1, q.x() + t * (r.x() - q.x()), q.y() + t * (r.y() - q.y()));
    f.segment(p, u, st(pal::light_grey).width(1));
  }
  f.add(p, lab(pal::black, "p", 180));
  f.add(q, lab(pal::blue, "q", -45));
  f.add(r, lab(pal::blue, "r", 45));
  f.add(Point(1, 1.5, 0.25), lab(pal::green, "u", 0).size(2.5));
  f.label(Point(1, -0.3, 1.4), "Δ(p, q, r) > 0: counter-clockwise", st(pal::green));
  dr::PlaneView v = plane(3);
  v.omega = false;
  dr::save(f, v, out_dir() / "fig-3-5-orientation.svg");
}

void fig_3_6() {  // a line on the sphere: a great circle
  dr::Figure f;
  const Point p(1, 1, 0), q(1, 0, 1.5);
  f.add(t2::join(p, q), st(pal::blue).width(2).arrow().label("p ∨ q"));
  f.add(p, lab(pal::blue, "p", -45));
  f.add(q, lab(pal::blue, "q", 135));
  f.add(t2::antipode(p), lab(pal::red, "¬p", 135));
  f.add(t2::antipode(q), lab(pal::red, "¬q", -45));
  dr::save(f, sphere(), out_dir() / "fig-3-6-line-sphere.svg");
}

void fig_3_7() {  // a segment on the sphere: the shorter arc
  dr::Figure f;
  f.add(t2::join(Point(1, 1, -0.5), Point(1, -1, 1.5)), st(pal::pale_grey).width(1));
  add_scene(f, "fig-3-7.scene", pal::blue);
  dr::save(f, sphere(), out_dir() / "fig-3-7-segment-sphere.svg");
}

void fig_3_8_to_3_10() {
  const struct {
    const char* scene;
    const char* out;
  } cases[] = {{"fig-3-8.scene", "fig-3-8-segment-front.svg"},
               {"fig-3-9.scene", "fig-3-9-segment-back.svg"},
               {"fig-3-10.scene", "fig-3-10-segment-front-to-back.svg"}};
  for (const auto& c : cases) {
    dr::Figure f;
    add_scene(f, c.scene, pal::blue);
    dr::save_both(f, plane(4), sphere(), out_dir() / c.out);
  }
}

dr::Figure sides_scene() {
  dr::Figure f;
  const Point a(1, 1, 0.5), b(1, -1, -1);
  const t2::Line r = t2::join(a, b);
  f.add(r, st(pal::blue).width(2).arrow().shade().label("r").label_angle(150));
  // Four test points; their captions come from the exact predicate r ⋄ p.
  const Point pts[] = {Point(1, -2, 1.6), Point(-1, -1.2, 0.8), Point(1, 1.3, -2.2), Point(-1, 2.7, -0.9)};
  for (const Point& p : pts) {
    const t2::Sign s = t2::side(r, p);
    const std::string text = std::string(p.w() > 0 ? "front" : "back") + ", r ⋄ p " + (s > 0 ? "> 0" : "< 0");
    f.add(p, lab(s > 0 ? pal::green : pal::red, text).size(3));
  }
  return f;
}

void fig_3_11() { dr::save(sides_scene(), plane(3), out_dir() / "fig-3-11-sides-planar.svg"); }
void fig_3_12() { dr::save(sides_scene(), sphere(), out_dir() / "fig-3-12-sides-sphere.svg"); }

}  // namespace

std::vector<Entry> thesis3() {
  return {
      {"3.1", "fig-3-1-t1-circle.svg",
       "T¹ as the unit circle: [w, x] at the direction of (w, x); the front half (w > 0) solid, the back half dashed, ±∞ at the top and bottom.",
       fig_3_1},
      {"3.2", "fig-3-2-t1-lines.svg",
       "T¹ as two copies of the real line (without ±∞). Drawn at x/w, the back copy is run through backwards.",
       fig_3_2},
      {"3.3", "fig-3-3-planar-model.svg",
       "The planar (two-sided) model: front points filled, back points hollow and dashed, p and ¬p at the same spot, Ω the ring on which r = [0, −1, 1] sits at its direction.",
       fig_3_3},
      {"3.4", "fig-3-4-spherical-model.svg",
       "The spherical model of the same points: central projection to the unit sphere, front = upper hemisphere, Ω = the equator, antipodes diametrically opposite.",
       fig_3_4},
      {"3.5", "fig-3-5-orientation.svg",
       "Orientation: as u runs from q to r, the segment pu turns counter-clockwise about p, so Δ(p, q, r) > 0.",
       fig_3_5},
      {"3.6", "fig-3-6-line-sphere.svg",
       "A line of T² in the spherical model: the great circle through p, q, ¬p, ¬q (arrow: its orientation).",
       fig_3_6},
      {"3.7", "fig-3-7-segment-sphere.svg",
       "A segment in the spherical model: the shorter arc of the great circle through its endpoints.",
       fig_3_7},
      {"3.8", "fig-3-8-segment-front.svg",
       "A segment with both endpoints on the front: the Euclidean segment (planar model, left; sphere, right).",
       fig_3_8_to_3_10},
      {"3.9", "fig-3-9-segment-back.svg",
       "Both endpoints on the back: the Euclidean segment, dashed.",
       nullptr},
      {"3.10", "fig-3-10-segment-front-to-back.svg",
       "From the front to the back: two half-rays, from p₀ away from ¬p₁ (solid) and from p₁ away from ¬p₀ (dashed), meeting at a point of Ω.",
       nullptr},
      {"3.11", "fig-3-11-sides-planar.svg",
       "The two sides of a line in the planar model: the positive side is a front half-plane (shaded) plus the opposite back half-plane (hatched).",
       fig_3_11},
      {"3.12", "fig-3-12-sides-sphere.svg",
       "The two sides of a line in the spherical model: two hemispheres (the positive one shaded).",
       fig_3_12},
  };
}

}  // namespace gallery
