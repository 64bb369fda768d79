#include "model_picture.hpp"


#include <algorithm>
#include <cmath>

#include "t2/draw/scene_figure.hpp"
#include "t2/kernel/error.hpp"
#include "t2/kernel/io.hpp"

namespace t2cli {

namespace dr = t2::draw;

void add_drawing_options(Arguments& app, AnswerDrawing& d, const std::string& what) {
  app.add_option("--svg", d.svg, "also draw " + what + " to OUT (SVG, atomically)")->type_name("OUT");
  app.add_option("--model", d.model, "the models drawn: plane, sphere or both (default both)")
      ->type_name("M")
      ->check(IsMember({"plane", "sphere", "both"}));
  app.add_option("--scene", d.scene,
                 "also write the answer as a scene file to OUT (atomically), styled to be drawn over\n"
                 "the input: t2 draw FILE OUT -o fig.svg")
      ->type_name("OUT");
}

t2::SceneStyle style_of(std::string_view attributes) {
  t2::SceneStyle st;
  std::size_t b = 0;
  while (b < attributes.size()) {
    std::size_t e = attributes.find(' ', b);
    if (e == std::string_view::npos) e = attributes.size();
    const std::string_view word = attributes.substr(b, e - b);
    const std::size_t eq = word.find('=');
    if (!word.empty()) t2::set_scene_attribute(st, word.substr(0, eq), word.substr(eq + 1), std::nullopt);
    b = e + 1;
  }
  return st;
}

t2::ScenePoint scene_point(const t2::Point& p, t2::SceneStyle style) { return t2::ScenePoint{p, 0, {}, std::move(style)}; }

namespace {

// Grows r to the distance from the origin of the finite point p.
void reach(double& r, const t2::Point& p) {
  if (p.w() == 0) return;
  const double d = std::hypot(p.x() / p.w(), p.y() / p.w());
  if (std::isfinite(d)) r = std::max(r, d);
}

dr::PlaneView view_of_radius(double r) {
  dr::PlaneView v;
  v.half_width = std::max(1.0, 1.2 * r);
  return v;
}

}  // namespace

dr::PlaneView fit_plane(std::span<const t2::Point> points) {
  double r = 0;
  for (const auto& p : points) reach(r, p);
  return view_of_radius(r);
}

dr::PlaneView fit_plane(const t2::Scene& s) {
  double r = 0;
  for (const auto& p : s.points) reach(r, p.point);
  for (const auto& g : s.segments) {
    reach(r, g.a.point);
    reach(r, g.b.point);
  }
  for (const auto& g : s.polygons)
    for (const auto& v : g.vertices) reach(r, v.point);
  for (const auto& g : s.lines) {
    reach(r, g.a.point);
    reach(r, g.b.point);
  }
  for (const auto& g : s.circles) {
    // A finite or beyond-infinity circle reaches |C| + |P − C| from the origin.
    const t2::Point &c = g.center.point, &p = g.through.point;
    if (c.w() == 0 || p.w() == 0) {
      reach(r, c);
      reach(r, p);
      continue;
    }
    const double cx = c.x() / c.w(), cy = c.y() / c.w();
    const double far = std::hypot(cx, cy) + std::hypot(p.x() / p.w() - cx, p.y() / p.w() - cy);
    if (std::isfinite(far)) r = std::max(r, far);
  }
  return view_of_radius(r);
}

std::string render_model(const dr::Figure& f, const std::string& model, const dr::PlaneView& plane,
                         const dr::SphereView& sphere, dr::Format format) {
  if (model == "plane") return dr::render(f, plane, format);
  if (model == "sphere") return dr::render(f, sphere, format);
  return dr::render_both(f, plane, sphere, format);
}

dr::Figure compose(std::span<const t2::Scene> scenes, dr::PlaneView& plane) {
  dr::Figure f;
  plane = dr::PlaneView();
  plane.half_width = 0;
  for (const auto& s : scenes) {
    dr::add_scene(f, s);
    plane.half_width = std::max(plane.half_width, fit_plane(s).half_width);
  }
  return f;
}

void write_answer(const AnswerDrawing& d, const t2::Scene& input, t2::Scene answer, const std::string& header) {
  answer.name = d.scene.empty() ? "<answer>" : d.scene;
  if (!d.svg.empty()) {
    const t2::Scene both[] = {input, answer};
    dr::PlaneView plane;
    const dr::Figure f = compose(both, plane);
    t2::write_file_atomically(d.svg, render_model(f, d.model, plane));
  }
  if (!d.scene.empty()) t2::write_file_atomically(d.scene, "# " + header + "\n" + t2::to_string(answer));
}

}  // namespace t2cli
