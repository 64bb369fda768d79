// Power-law fits and the log-log plot: see loglog.hpp.
#include <t2/draw/loglog.hpp>

#include <cairo-svg.h>
#include <cairo.h>
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <regex>
#include <set>

namespace t2::draw {

bool fit_defined(std::span<const double> n, std::span<const double> t) {
  std::set<double> sizes;
  for (std::size_t i = 0; i < n.size() && i < t.size(); ++i)
    if (n[i] > 0 && t[i] > 0) sizes.insert(n[i]);
  return sizes.size() >= 2;
}

PowerLaw fit_power_law(std::span<const double> n, std::span<const double> t) {
  PowerLaw f;
  double sx = 0, sy = 0;
  std::vector<std::pair<double, double>> xy;
  for (std::size_t i = 0; i < n.size() && i < t.size(); ++i) {
    if (n[i] <= 0 || t[i] <= 0) continue;
    xy.emplace_back(std::log(n[i]), std::log(t[i]));
    sx += xy.back().first;
    sy += xy.back().second;
  }
  f.points = xy.size();
  if (!fit_defined(n, t)) return f;
  const double mx = sx / double(xy.size()), my = sy / double(xy.size());
  double sxx = 0, sxy = 0;  // centred sums: no cancellation between large logs
  for (const auto& [x, y] : xy) {
    sxx += (x - mx) * (x - mx);
    sxy += (x - mx) * (y - my);
  }
  f.exponent = sxy / sxx;
  f.constant = std::exp(my - f.exponent * mx);
  return f;
}

namespace {

constexpr double kWidth = 640, kHeight = 440;
constexpr double kLeft = 72, kRight = 24, kTop = 44, kBottom = 56;

struct Rgb {
  double r, g, b;
};
const Rgb kColours[] = {{0.12, 0.47, 0.71}, {0.84, 0.15, 0.16}, {0.17, 0.63, 0.17},
                        {0.58, 0.40, 0.74}, {1.00, 0.50, 0.05}, {0.55, 0.34, 0.29}};

cairo_status_t append(void* closure, const unsigned char* data, unsigned int length) {
  static_cast<std::string*>(closure)->append(reinterpret_cast<const char*>(data), length);
  return CAIRO_STATUS_SUCCESS;
}

// The decades [lo, hi] that hold the values (at least one decade wide).
std::pair<int, int> decades(double lo, double hi) {
  int a = static_cast<int>(std::floor(std::log10(lo))), b = static_cast<int>(std::ceil(std::log10(hi)));
  if (b <= a) b = a + 1;
  return {a, b};
}

std::string power_of_ten(int k) { return k >= -2 && k <= 5 ? fmt::format("{:g}", std::pow(10, k)) : fmt::format("1e{}", k); }

void text(cairo_t* cr, double x, double y, const std::string& s, int halign, double size = 12) {
  cairo_set_font_size(cr, size);
  cairo_text_extents_t e;
  cairo_text_extents(cr, s.c_str(), &e);
  const double dx = halign < 0 ? 0 : halign == 0 ? -e.width / 2 - e.x_bearing : -e.width - e.x_bearing;
  cairo_move_to(cr, x + dx, y);
  cairo_show_text(cr, s.c_str());
}

}  // namespace

std::string loglog_svg(const std::vector<Series>& series, const std::string& title, const std::string& y_label) {
  double nlo = std::numeric_limits<double>::max(), nhi = 0, tlo = nlo, thi = 0;
  for (const auto& s : series)
    for (std::size_t i = 0; i < s.n.size() && i < s.t.size(); ++i)
      if (s.n[i] > 0 && s.t[i] > 0) {
        nlo = std::min(nlo, s.n[i]), nhi = std::max(nhi, s.n[i]);
        tlo = std::min(tlo, s.t[i]), thi = std::max(thi, s.t[i]);
      }
  if (nhi == 0) nlo = nhi = tlo = thi = 1;  // nothing measured: empty axes
  const auto [xa, xb] = decades(nlo, nhi);
  const auto [ya, yb] = decades(tlo, thi);
  const double pw = kWidth - kLeft - kRight, ph = kHeight - kTop - kBottom;
  auto X = [&, xa = xa, xb = xb](double n) { return kLeft + pw * (std::log10(n) - xa) / (xb - xa); };
  auto Y = [&, ya = ya, yb = yb](double t) { return kTop + ph * (1 - (std::log10(t) - ya) / (yb - ya)); };

  std::string bytes;
  cairo_surface_t* surface = cairo_svg_surface_create_for_stream(append, &bytes, kWidth, kHeight);
  cairo_t* cr = cairo_create(surface);
  cairo_select_font_face(cr, "DejaVu Sans", CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_NORMAL);
  cairo_set_source_rgb(cr, 1, 1, 1);
  cairo_paint(cr);
  // Grid and ticks at every decade, the frame, the labels.
  cairo_set_line_width(cr, 0.6);
  cairo_set_source_rgb(cr, 0.85, 0.85, 0.85);
  for (int k = xa; k <= xb; ++k) cairo_move_to(cr, X(std::pow(10, k)), kTop), cairo_line_to(cr, X(std::pow(10, k)), kTop + ph);
  for (int k = ya; k <= yb; ++k) cairo_move_to(cr, kLeft, Y(std::pow(10, k))), cairo_line_to(cr, kLeft + pw, Y(std::pow(10, k)));
  cairo_stroke(cr);
  cairo_set_source_rgb(cr, 0, 0, 0);
  cairo_set_line_width(cr, 1);
  cairo_rectangle(cr, kLeft, kTop, pw, ph);
  cairo_stroke(cr);
  for (int k = xa; k <= xb; ++k) text(cr, X(std::pow(10, k)), kTop + ph + 16, power_of_ten(k), 0);
  for (int k = ya; k <= yb; ++k) text(cr, kLeft - 6, Y(std::pow(10, k)) + 4, power_of_ten(k), 1);
  text(cr, kLeft + pw / 2, kHeight - 14, "n (log scale)", 0);
  text(cr, kLeft + pw / 2, 24, title, 0, 14);
  cairo_save(cr);
  cairo_translate(cr, 16, kTop + ph / 2);
  cairo_rotate(cr, -M_PI / 2);
  text(cr, 0, 0, y_label, 0);
  cairo_restore(cr);
  // The series, clipped to the frame.
  cairo_save(cr);
  cairo_rectangle(cr, kLeft, kTop, pw, ph);
  cairo_clip(cr);
  for (std::size_t j = 0; j < series.size(); ++j) {
    const auto& s = series[j];
    const Rgb c = kColours[j % std::size(kColours)];
    cairo_set_source_rgb(cr, c.r, c.g, c.b);
    cairo_set_line_width(cr, 1.8);
    cairo_set_dash(cr, nullptr, 0, 0);
    bool first = true;
    for (std::size_t i = 0; i < s.n.size() && i < s.t.size(); ++i) {
      if (s.n[i] <= 0 || s.t[i] <= 0) continue;
      first ? cairo_move_to(cr, X(s.n[i]), Y(s.t[i])) : cairo_line_to(cr, X(s.n[i]), Y(s.t[i]));
      first = false;
    }
    cairo_stroke(cr);
    for (std::size_t i = 0; i < s.n.size() && i < s.t.size(); ++i) {
      if (s.n[i] <= 0 || s.t[i] <= 0) continue;
      cairo_arc(cr, X(s.n[i]), Y(s.t[i]), 3.5, 0, 2 * M_PI);
      cairo_fill(cr);
    }
    if (fit_defined(s.n, s.t)) {  // the fitted line across the whole frame, dashed
      const PowerLaw f = fit_power_law(s.n, s.t);
      const double n0 = std::pow(10, xa), n1 = std::pow(10, xb);
      const double dash[] = {5, 4};
      cairo_set_dash(cr, dash, 2, 0);
      cairo_set_line_width(cr, 0.9);
      cairo_move_to(cr, X(n0), Y(f.constant * std::pow(n0, f.exponent)));
      cairo_line_to(cr, X(n1), Y(f.constant * std::pow(n1, f.exponent)));
      cairo_stroke(cr);
    }
  }
  cairo_restore(cr);
  // The legend, top left inside the frame.
  for (std::size_t j = 0; j < series.size(); ++j) {
    const auto& s = series[j];
    const Rgb c = kColours[j % std::size(kColours)];
    const double y = kTop + 18 + 18 * double(j);
    cairo_set_source_rgb(cr, 1, 1, 1);
    cairo_rectangle(cr, kLeft + 8, y - 13, 190, 18);
    cairo_fill(cr);
    cairo_set_source_rgb(cr, c.r, c.g, c.b);
    cairo_set_dash(cr, nullptr, 0, 0);
    cairo_set_line_width(cr, 1.8);
    cairo_move_to(cr, kLeft + 12, y - 4);
    cairo_line_to(cr, kLeft + 34, y - 4);
    cairo_stroke(cr);
    cairo_set_source_rgb(cr, 0, 0, 0);
    const std::string growth =
        fit_defined(s.n, s.t) ? fmt::format("  ~ n^{:.2f}", fit_power_law(s.n, s.t).exponent) : std::string();
    text(cr, kLeft + 40, y, s.name + growth, -1);
  }
  cairo_destroy(cr);
  cairo_surface_finish(surface);
  cairo_surface_destroy(surface);
  // Cairo numbers SVG surfaces with a process-wide counter (the plot's other ids are per
  // surface): one plot per document, so its surface is always number 1.
  static const std::regex surface_id(R"(id="surface\d+")");
  return std::regex_replace(bytes, surface_id, R"(id="surface1")");
}

}  // namespace t2::draw
