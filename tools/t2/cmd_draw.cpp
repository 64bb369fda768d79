// t2 draw: a scene file drawn in the planar model, the spherical model or both.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "command.hpp"
#include "t2/draw.hpp"
#include "t2/io.hpp"
#include "t2/scene.hpp"

namespace t2cli {
namespace {

const char* const kHelp =
    "Usage: t2 draw FILE [--model plane|sphere|both] [--view LAT,LON] [--format svg|png|pdf] -o OUT\n"
    "\n"
    "Draws the points, segments and polygons of the scene file FILE (see the README, section\n"
    "\"Scene files\") in the planar model of T2 (front solid and filled, back dashed and hollow,\n"
    "Omega a ring around the view), in the spherical model (seen from latitude LAT and longitude\n"
    "LON, degrees; default 25,-65), or both side by side (the default). The planar view is fitted\n"
    "to the proper points of the scene. The format is taken from --format, else from the\n"
    "extension of OUT. A bad scene file fails with file:line: message and exit status 2, and no\n"
    "output is written; a scene that is undefined in T2 exits with status 3.\n"
    "\n"
    "Example: t2 draw triangle.scene --model both -o triangle.svg\n";

const char* const kPalette[] = {"#1f77b4", "#d62728", "#2ca02c", "#ff7f0e", "#9467bd", "#8c564b"};

int run(Args args) {
  std::string file, out, model = "both", format;
  t2::draw::SphereView sphere;
  for (std::size_t i = 0; i < args.size(); ++i) {
    const std::string& a = args[i];
    auto value = [&]() -> const std::string& {
      if (i + 1 >= args.size()) throw UsageError(a + " needs a value");
      return args[++i];
    };
    if (a == "--model") {
      model = value();
      if (model != "plane" && model != "sphere" && model != "both")
        throw UsageError("--model must be plane, sphere or both, not '" + model + "'");
    } else if (a == "--view") {
      const std::string& v = value();
      double lat = 0, lon = 0;
      char comma = 0, extra = 0;
      if (std::sscanf(v.c_str(), "%lf %c %lf %c", &lat, &comma, &lon, &extra) != 3 || comma != ',' ||
          !std::isfinite(lat) || !std::isfinite(lon) || std::fabs(lat) > 90)
        throw UsageError("--view wants LAT,LON in degrees with |LAT| <= 90, not '" + v + "'");
      sphere.lat = lat;
      sphere.lon = lon;
    } else if (a == "--format") {
      format = value();
      if (format != "svg" && format != "png" && format != "pdf")
        throw UsageError("--format must be svg, png or pdf, not '" + format + "'");
    } else if (a == "-o" || a == "--output") {
      out = value();
    } else if (!a.empty() && a[0] == '-') {
      throw UsageError("unknown option " + a);
    } else if (file.empty()) {
      file = a;
    } else {
      throw UsageError("one scene file only ('" + file + "', then '" + a + "')");
    }
  }
  if (file.empty()) throw UsageError("no scene file given");
  if (out.empty()) throw UsageError("no output file given (-o OUT)");
  const t2::draw::Format fmt = format.empty() ? t2::draw::format_of(out)
                               : format == "png" ? t2::draw::Format::png
                               : format == "pdf" ? t2::draw::Format::pdf
                                                 : t2::draw::Format::svg;

  const t2::Scene scene = t2::read_scene(file);  // ParseError (file:line) escapes: exit 2
  namespace dr = t2::draw;
  dr::Figure fig;
  double extent = 1;  // the planar view fits every proper point
  auto fit = [&](const t2::Point& p) {
    if (p.w() == 0) return;
    extent = std::max({extent, std::fabs(p.x() / p.w()), std::fabs(p.y() / p.w())});
  };
  int colour = 0;
  for (const auto& poly : scene.polygons) {
    std::vector<t2::Point> v;
    for (const auto& p : poly.vertices) {
      v.push_back(p.point);
      fit(p.point);
    }
    const char* c = kPalette[colour++ % 6];
    fig.add(v, dr::Style().color(c).width(1.8).fill(c).fill_opacity(0.18));
  }
  for (const auto& s : scene.segments) {
    fit(s.a.point);
    fit(s.b.point);
    fig.segment(s.a.point, s.b.point, dr::Style().color(kPalette[colour++ % 6]).width(1.8));
  }
  for (const auto& p : scene.points) {
    fit(p.point);
    fig.add(p.point, dr::Style().label(p.label));
  }
  for (const auto& s : scene.segments)
    for (const auto* p : {&s.a, &s.b})
      if (!p->label.empty() || scene.points.empty()) fig.add(p->point, dr::Style().label(p->label).size(2.8));
  dr::PlaneView plane;
  plane.half_width = extent * 1.1;
  std::string bytes;
  if (model == "plane") bytes = dr::render(fig, plane, fmt);
  if (model == "sphere") bytes = dr::render(fig, sphere, fmt);
  if (model == "both") bytes = dr::render_both(fig, plane, sphere, fmt);
  t2::write_file_atomically(out, bytes);
  return kOk;
}

}  // namespace

T2_COMMAND({"draw", "draw a scene file in the planar and/or spherical model (SVG, PNG, PDF)", kHelp, run})

}  // namespace t2cli
