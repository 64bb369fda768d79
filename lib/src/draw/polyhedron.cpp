// Polyhedra drawn with Cairo: orthographic view, shaded front faces, dashed hidden edges.
#include "t2/draw/polyhedron.hpp"

#include <cairo-pdf.h>
#include <cairo-svg.h>
#include <cairo.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>
#include <stdexcept>
#include <vector>

#include "t2/kernel/io.hpp"

namespace t2::draw {

namespace {

cairo_status_t append_bytes(void* closure, const unsigned char* data, unsigned int length) {
  static_cast<std::string*>(closure)->append(reinterpret_cast<const char*>(data), length);
  return CAIRO_STATUS_SUCCESS;
}

struct V3 {
  double x, y, z;
};
V3 sub(const Point3& a, const Point3& b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
V3 cross(const V3& a, const V3& b) { return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x}; }
double dot(const V3& a, const V3& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }

// Newell's normal of a face (any planar polygon, robust to collinear first vertices).
V3 normal(const Polyhedron& P, const std::vector<std::uint32_t>& f) {
  V3 n{0, 0, 0};
  for (std::size_t k = 0; k < f.size(); ++k) {
    const Point3 &a = P.vertices[f[k]], &b = P.vertices[f[(k + 1) % f.size()]];
    n.x += (a.y - b.y) * (a.z + b.z);
    n.y += (a.z - b.z) * (a.x + b.x);
    n.z += (a.x - b.x) * (a.y + b.y);
  }
  return n;
}

}  // namespace

std::string render_polyhedron(const Polyhedron& P, const View3& v, Format fmt, std::span<const Point3> points) {
  const double az = v.azimuth * std::numbers::pi / 180, el = v.elevation * std::numbers::pi / 180;
  const V3 d{std::cos(el) * std::cos(az), std::cos(el) * std::sin(az), std::sin(el)};  // towards the viewer
  const V3 right{-std::sin(az), std::cos(az), 0};
  const V3 up = cross(d, right);
  V3 c{0, 0, 0};  // the middle of the bounding box, and the radius around it
  double lo[3] = {INFINITY, INFINITY, INFINITY}, hi[3] = {-INFINITY, -INFINITY, -INFINITY};
  for (const Point3& p : P.vertices) {
    const double q[3] = {p.x, p.y, p.z};
    for (int k = 0; k < 3; ++k) lo[k] = std::min(lo[k], q[k]), hi[k] = std::max(hi[k], q[k]);
  }
  if (!P.vertices.empty()) c = {(lo[0] + hi[0]) / 2, (lo[1] + hi[1]) / 2, (lo[2] + hi[2]) / 2};
  double r = 0;
  for (const Point3& p : P.vertices) r = std::max(r, std::sqrt(dot(sub(p, {c.x, c.y, c.z}), sub(p, {c.x, c.y, c.z}))));
  if (r == 0) r = 1;
  const double size = v.size, s = 0.45 * size / r;
  auto px = [&](const Point3& p) {
    const V3 w = sub(p, {c.x, c.y, c.z});
    return std::pair{size / 2 + s * dot(w, right), size / 2 - s * dot(w, up)};
  };
  std::vector<double> facing(P.faces.size());  // n·d / |n|
  for (std::size_t f = 0; f < P.faces.size(); ++f) {
    const V3 n = normal(P, P.faces[f]);
    const double len = std::sqrt(dot(n, n));
    facing[f] = len > 0 ? dot(n, d) / len : 0;
  }
  std::map<std::pair<std::uint32_t, std::uint32_t>, bool> visible;  // edge: seen from a visible face
  for (std::size_t f = 0; f < P.faces.size(); ++f)
    for (std::size_t k = 0; k < P.faces[f].size(); ++k) {
      std::uint32_t a = P.faces[f][k], b = P.faces[f][(k + 1) % P.faces[f].size()];
      if (a > b) std::swap(a, b);
      visible[{a, b}] = visible[{a, b}] || facing[f] > 0;
    }

  std::string bytes;
  cairo_surface_t* surface = nullptr;
  switch (fmt) {
    case Format::svg:
      surface = cairo_svg_surface_create_for_stream(append_bytes, &bytes, size, size);
      cairo_svg_surface_restrict_to_version(surface, CAIRO_SVG_VERSION_1_1);
      cairo_svg_surface_set_document_unit(surface, CAIRO_SVG_UNIT_PX);
      break;
    case Format::pdf: surface = cairo_pdf_surface_create_for_stream(append_bytes, &bytes, size, size); break;
    case Format::png: surface = cairo_image_surface_create(CAIRO_FORMAT_ARGB32, v.size, v.size); break;
  }
  cairo_t* cr = cairo_create(surface);
  cairo_set_source_rgb(cr, 1, 1, 1);
  cairo_paint(cr);
  cairo_set_line_join(cr, CAIRO_LINE_JOIN_ROUND);
  cairo_set_line_cap(cr, CAIRO_LINE_CAP_ROUND);
  auto edge = [&](std::uint32_t a, std::uint32_t b) {
    const auto [x0, y0] = px(P.vertices[a]);
    const auto [x1, y1] = px(P.vertices[b]);
    cairo_move_to(cr, x0, y0);
    cairo_line_to(cr, x1, y1);
    cairo_stroke(cr);
  };
  //> hidden-edges
  const double dash[] = {5, 4};  // hidden edges first, dashed and grey
  cairo_set_dash(cr, dash, 2, 0);
  cairo_set_line_width(cr, 1.2);
  cairo_set_source_rgb(cr, 0.55, 0.55, 0.55);
  for (const auto& [e, seen] : visible)
    if (!seen) edge(e.first, e.second);
  cairo_set_dash(cr, nullptr, 0, 0);
  for (const Point3& p : points) {  // the input points, small and grey
    const auto [x, y] = px(p);
    cairo_arc(cr, x, y, 1.6, 0, 2 * std::numbers::pi);
    cairo_fill(cr);
  }
  for (std::size_t f = 0; f < P.faces.size(); ++f) {  // visible faces, lit from the viewer
    if (facing[f] <= 0) continue;
    for (std::size_t k = 0; k < P.faces[f].size(); ++k) {
      const auto [x, y] = px(P.vertices[P.faces[f][k]]);
      k == 0 ? cairo_move_to(cr, x, y) : cairo_line_to(cr, x, y);
    }
    cairo_close_path(cr);
    const double t = 0.35 + 0.65 * facing[f];
    cairo_set_source_rgba(cr, 0.12 + 0.5 * (1 - t), 0.47 + 0.35 * (1 - t), 0.71 + 0.2 * (1 - t), 0.55);
    cairo_fill(cr);
  }
  cairo_set_line_width(cr, 1.8);  // visible edges on top, solid and black
  cairo_set_source_rgb(cr, 0, 0, 0);
  for (const auto& [e, seen] : visible)
    if (seen) edge(e.first, e.second);
  //< hidden-edges
  const cairo_status_t st = cairo_status(cr);
  cairo_destroy(cr);
  if (fmt == Format::png) cairo_surface_write_to_png_stream(surface, append_bytes, &bytes);
  cairo_surface_finish(surface);
  cairo_surface_destroy(surface);
  if (st != CAIRO_STATUS_SUCCESS) throw std::runtime_error(std::string("cairo: ") + cairo_status_to_string(st));
  return bytes;
}

bool save_polyhedron(const Polyhedron& P, const View3& v, const std::filesystem::path& path,
                     std::span<const Point3> points) {
  write_file_atomically(path, render_polyhedron(P, v, format_of(path), points));
  return true;
}

}  // namespace t2::draw
