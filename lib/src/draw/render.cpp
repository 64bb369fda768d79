// The Cairo backend: paints display lists as SVG, PNG or PDF (see t2/draw/render.hpp).
#include <cairo-pdf.h>
#include <cairo-svg.h>
#include <cairo.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <memory>
#include <numbers>
#include <string>
#include <string_view>

#include "t2/draw/render.hpp"
#include "t2/kernel/error.hpp"
#include "t2/kernel/io.hpp"

namespace t2::draw {

namespace {

void set_rgb(cairo_t* cr, const std::string& hex, double alpha) {
  unsigned r = 0, g = 0, b = 0;
  if (hex.size() == 7 && hex[0] == '#' && std::sscanf(hex.c_str() + 1, "%2x%2x%2x", &r, &g, &b) == 3) {
    cairo_set_source_rgba(cr, r / 255.0, g / 255.0, b / 255.0, alpha);
  } else {
    throw BadInput("colour '" + hex + "' is not of the form #rrggbb");
  }
}

void trace(cairo_t* cr, const Shape& s) {
  cairo_new_path(cr);
  for (std::size_t i = 0; i < s.pts.size(); ++i) {
    if (i == 0)
      cairo_move_to(cr, s.pts[i].x, s.pts[i].y);
    else
      cairo_line_to(cr, s.pts[i].x, s.pts[i].y);
  }
  if (s.closed) cairo_close_path(cr);
}

void marker_path(cairo_t* cr, const Shape& s) {
  const double x = s.pts[0].x, y = s.pts[0].y, r = s.radius;
  cairo_new_path(cr);
  switch (s.marker) {
    case Marker::square: cairo_rectangle(cr, x - r, y - r, 2 * r, 2 * r); break;
    case Marker::diamond:
      cairo_move_to(cr, x, y - 1.3 * r);
      cairo_line_to(cr, x + 1.3 * r, y);
      cairo_line_to(cr, x, y + 1.3 * r);
      cairo_line_to(cr, x - 1.3 * r, y);
      cairo_close_path(cr);
      break;
    case Marker::cross:
      cairo_move_to(cr, x - r, y - r);
      cairo_line_to(cr, x + r, y + r);
      cairo_move_to(cr, x - r, y + r);
      cairo_line_to(cr, x + r, y - r);
      break;
    case Marker::none: break;
    case Marker::dot: cairo_arc(cr, x, y, r, 0, 2 * std::numbers::pi); break;
  }
}

void paint(cairo_t* cr, const std::vector<Shape>& shapes, double dx, double dy, double width) {
  cairo_save(cr);
  cairo_translate(cr, dx, dy);
  cairo_set_line_join(cr, CAIRO_LINE_JOIN_ROUND);
  cairo_set_line_cap(cr, CAIRO_LINE_CAP_BUTT);
  cairo_select_font_face(cr, "DejaVu Sans", CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_NORMAL);
  for (const Shape& s : shapes) {
    if (s.opacity == 0 || s.pts.empty()) continue;
    cairo_set_dash(cr, s.dash.data(), static_cast<int>(s.dash.size()), 0);
    cairo_set_line_width(cr, s.width);
    switch (s.kind) {
      case ShapeKind::path:
        if (!s.fill.empty()) {
          trace(cr, s);
          if (s.hatch) {
            // Hatching: parallel diagonal strokes clipped to the region.
            cairo_save(cr);
            cairo_clip(cr);
            set_rgb(cr, s.fill, std::min(1.0, s.fill_opacity));
            cairo_set_dash(cr, nullptr, 0, 0);
            cairo_set_line_width(cr, 1);
            double x0 = 1e300, x1 = -1e300, y0 = 1e300, y1 = -1e300;
            for (const auto& p : s.pts) {
              x0 = std::min(x0, p.x), x1 = std::max(x1, p.x), y0 = std::min(y0, p.y), y1 = std::max(y1, p.y);
            }
            for (double c = std::floor((x0 + y0) / 7) * 7; c <= x1 + y1; c += 7) {
              cairo_move_to(cr, c - y0, y0);
              cairo_line_to(cr, c - y1, y1);
            }
            cairo_stroke(cr);
            cairo_restore(cr);
          } else {
            set_rgb(cr, s.fill, s.fill_opacity);
            cairo_fill(cr);
          }
        }
        if (!s.stroke.empty()) {
          trace(cr, s);
          set_rgb(cr, s.stroke, s.opacity);
          cairo_stroke(cr);
        }
        break;
      case ShapeKind::marker:
        if (s.marker == Marker::none) break;
        marker_path(cr, s);
        if (s.marker != Marker::cross && !s.fill.empty()) {
          set_rgb(cr, s.fill, s.opacity);
          cairo_fill_preserve(cr);
        }
        set_rgb(cr, s.stroke, s.opacity);
        cairo_stroke(cr);
        break;
      case ShapeKind::text: {
        cairo_set_font_size(cr, s.font_size);
        cairo_text_extents_t ext;
        cairo_text_extents(cr, s.text.c_str(), &ext);
        double x = s.pts[0].x;
        if (s.halign == 0) x -= ext.x_advance / 2;
        if (s.halign == 1) x -= ext.x_advance;
        x = std::max(2.0, std::min(x, width - ext.x_advance - 2));  // keep it inside the picture
        if (s.halo) {  // a white halo keeps labels readable over lines
          cairo_move_to(cr, x, s.pts[0].y);
          cairo_text_path(cr, s.text.c_str());
          cairo_set_source_rgba(cr, 1, 1, 1, 0.85);
          cairo_set_line_width(cr, 3);
          cairo_set_dash(cr, nullptr, 0, 0);
          cairo_stroke(cr);
        }
        cairo_move_to(cr, x, s.pts[0].y);
        set_rgb(cr, s.stroke.empty() ? "#000000" : s.stroke, s.opacity);
        cairo_show_text(cr, s.text.c_str());
        break;
      }
    }
  }
  cairo_restore(cr);
}

cairo_status_t append(void* closure, const unsigned char* data, unsigned int length) {
  static_cast<std::string*>(closure)->append(reinterpret_cast<const char*>(data), length);
  return CAIRO_STATUS_SUCCESS;
}

/// Cairo numbers SVG ids (glyphs, surfaces, clips) with process-wide counters: renumber them
/// in order of first appearance so that the bytes do not depend on what was drawn before.
/// An id is a kind, a number and an optional "-number" suffix, found anywhere in the text
/// (leftmost first, as the regular expression (glyph|surface|…)(\d+)(-\d+)? would find them;
/// a plain scan, because std::regex took 60% of the time of drawing an animation).
std::string renumber_ids(const std::string& svg) {
  static constexpr std::array<std::string_view, 7> kinds{"glyph", "surface", "clip",  "mask",
                                                         "pattern", "image", "source"};
  const auto digits_end = [&svg](std::size_t k) {
    while (k < svg.size() && svg[k] >= '0' && svg[k] <= '9') ++k;
    return k;
  };
  std::map<std::string_view, std::map<std::string, int>> seen;  // kind -> old number -> new
  std::string out;
  out.reserve(svg.size());
  std::size_t last = 0;
  for (std::size_t i = 0; i < svg.size();) {
    // Most characters start no kind: one test of the first letter (seven compares at every
    // character took a fifth of the time of drawing an animation).
    const char c = svg[i];
    if (c != 'g' && c != 's' && c != 'c' && c != 'm' && c != 'p' && c != 'i') {
      ++i;
      continue;
    }
    const auto kind = std::find_if(kinds.begin(), kinds.end(), [&](std::string_view k) {
      return svg.compare(i, k.size(), k) == 0;
    });
    const std::size_t number = kind == kinds.end() ? i : i + kind->size();
    const std::size_t number_end = digits_end(number);
    if (kind == kinds.end() || number_end == number) {
      ++i;
      continue;
    }
    std::size_t end = number_end;
    if (end < svg.size() && svg[end] == '-' && digits_end(end + 1) > end + 1) end = digits_end(end + 1);
    auto& table = seen[*kind];
    const auto [pos, fresh] =
        table.try_emplace(svg.substr(number, number_end - number), static_cast<int>(table.size()));
    out.append(svg, last, i - last);
    out += *kind;
    out += std::to_string(pos->second);
    out.append(svg, number_end, end - number_end);
    i = last = end;
  }
  out.append(svg, last, std::string::npos);
  return out;
}

/// Paints one or more display lists side by side on a surface of the given format.
/// Each panel is a display list, its left edge and its width.
struct Panel {
  std::vector<Shape> shapes;
  double x;
  double width;
};

std::string paint_all(const std::vector<Panel>& panels, double width, double height, Format fmt) {
  std::string bytes;
  cairo_surface_t* surface = nullptr;
  switch (fmt) {
    case Format::svg:
      surface = cairo_svg_surface_create_for_stream(append, &bytes, width, height);
      cairo_svg_surface_restrict_to_version(surface, CAIRO_SVG_VERSION_1_1);
      cairo_svg_surface_set_document_unit(surface, CAIRO_SVG_UNIT_PX);
      break;
    case Format::pdf:
      surface = cairo_pdf_surface_create_for_stream(append, &bytes, width, height);
      cairo_pdf_surface_set_metadata(surface, CAIRO_PDF_METADATA_CREATOR, "t2");
      cairo_pdf_surface_set_metadata(surface, CAIRO_PDF_METADATA_CREATE_DATE, "2000-01-01T00:00:00");
      break;
    case Format::png:
      surface = cairo_image_surface_create(CAIRO_FORMAT_ARGB32, static_cast<int>(2 * width), static_cast<int>(2 * height));
      break;
  }
  cairo_t* cr = cairo_create(surface);
  if (fmt == Format::png) cairo_scale(cr, 2, 2);  // slides: twice the resolution
  cairo_set_source_rgb(cr, 1, 1, 1);
  cairo_paint(cr);
  for (const auto& p : panels) paint(cr, p.shapes, p.x, 0, p.width);
  const cairo_status_t st = cairo_status(cr);
  cairo_destroy(cr);
  if (fmt == Format::png) cairo_surface_write_to_png_stream(surface, append, &bytes);
  cairo_surface_finish(surface);
  cairo_surface_destroy(surface);
  if (st != CAIRO_STATUS_SUCCESS) throw std::runtime_error(std::string("cairo: ") + cairo_status_to_string(st));
  return fmt == Format::svg ? renumber_ids(bytes) : bytes;
}

}  // namespace

Format format_of(const std::filesystem::path& path) {
  const std::string e = path.extension().string();
  if (e == ".svg") return Format::svg;
  if (e == ".png") return Format::png;
  if (e == ".pdf") return Format::pdf;
  throw BadInput("cannot tell the format of '" + path.string() + "': use .svg, .png or .pdf");
}

namespace {
double band(const Figure& f) { return f.title().empty() ? 0 : title_band; }
}  // namespace

std::string render(const Figure& f, const PlaneView& v, Format fmt) {
  return paint_all({{display_list(f, v), 0, double(v.size)}}, v.size, v.size + band(f), fmt);
}
std::string render(const Figure& f, const SphereView& v, Format fmt) {
  return paint_all({{display_list(f, v), 0, double(v.size)}}, v.size, v.size + band(f), fmt);
}
std::string render(const Figure& f, const T1View& v, Format fmt) {
  const double h = v.model == T1Model::circle ? v.size : v.size * 0.5;
  return paint_all({{display_list(f, v), 0, double(v.size)}}, v.size, h, fmt);
}
std::string render_both(const Figure& f, const PlaneView& plane, const SphereView& sphere, Format fmt) {
  return paint_all({{display_list(f, plane), 0, double(plane.size)}, {display_list(f, sphere), double(plane.size), double(sphere.size)}},
                   plane.size + sphere.size,
                   std::max(plane.size, sphere.size) + band(f), fmt);
}

bool save(const Figure& f, const PlaneView& v, const std::filesystem::path& path) {
  return update_file_atomically(path, render(f, v, format_of(path)));
}
bool save(const Figure& f, const SphereView& v, const std::filesystem::path& path) {
  return update_file_atomically(path, render(f, v, format_of(path)));
}
bool save(const Figure& f, const T1View& v, const std::filesystem::path& path) {
  return update_file_atomically(path, render(f, v, format_of(path)));
}
bool save_both(const Figure& f, const PlaneView& plane, const SphereView& sphere, const std::filesystem::path& path) {
  return update_file_atomically(path, render_both(f, plane, sphere, format_of(path)));
}

void FigurePairs::save(const Figure& f, const std::string& name, const PlaneView& plane, const SphereView& sphere) {
  written_ += draw::save(f, plane, dir_ / (name + "-plane.svg"));
  written_ += draw::save(f, sphere, dir_ / (name + "-sphere.svg"));
  count_ += 2;
}

std::string FigurePairs::summary() const {
  return "figures: " + std::to_string(count_) + " in " + dir_.string() + " (" + std::to_string(written_) + " changed)";
}

std::filesystem::path figures_dir(int argc, char** argv, const std::filesystem::path& fallback) {
  for (int i = 1; i + 1 < argc; ++i)
    if (std::string(argv[i]) == "--figures") return argv[i + 1];
  return fallback;
}

}  // namespace t2::draw
