#include "model_picture.hpp"

#include <CLI/CLI.hpp>

#include <algorithm>
#include <cmath>

#include "t2/io.hpp"

namespace t2cli {

namespace dr = t2::draw;

void add_drawing_options(CLI::App& app, AnswerDrawing& d, const std::string& what) {
  app.add_option("--svg", d.svg, "also draw " + what + " to OUT (SVG, atomically)")->type_name("OUT");
  app.add_option("--model", d.model, "the models drawn: plane, sphere or both (default both)")
      ->type_name("M")
      ->check(CLI::IsMember({"plane", "sphere", "both"}));
}

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

std::string render_models(const dr::Figure& f, const std::vector<t2::Point>& points, const std::string& model) {
  return render_model(f, model, fit_plane(points));
}

void write_drawing(const AnswerDrawing& d, const dr::Figure& f, const dr::PlaneView& plane) {
  if (d.svg.empty()) return;
  t2::write_file_atomically(d.svg, render_model(f, d.model, plane));
}

}  // namespace t2cli
