// t2 draw: the picture of a scene file in the planar model, the spherical model, or both.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <optional>
#include <string>
#include <vector>

#include "command.hpp"
#include "t2/draw.hpp"
#include "t2/io.hpp"
#include "t2/scene.hpp"

namespace t2cli {
namespace {

namespace dr = t2::draw;

enum class Model { plane, sphere, both };

Model parse_model(const std::string& s) {
  if (s == "plane") return Model::plane;
  if (s == "sphere") return Model::sphere;
  if (s == "both") return Model::both;
  throw UsageError(fmt::format("--model must be plane, sphere or both, not '{}'", s));
}

dr::Format parse_format(const std::string& s) {
  if (s == "svg") return dr::Format::svg;
  if (s == "png") return dr::Format::png;
  if (s == "pdf") return dr::Format::pdf;
  throw UsageError(fmt::format("--format must be svg, png or pdf, not '{}'", s));
}

double parse_degrees(const std::string& s, const char* what, double limit) {
  char* end = nullptr;
  const double d = std::strtod(s.c_str(), &end);
  if (s.empty() || end != s.c_str() + s.size() || !std::isfinite(d) || std::fabs(d) > limit)
    throw UsageError(fmt::format("--view: {} must be a number of degrees in [-{}, {}], not '{}'", what,
                                 limit, limit, s));
  return d;
}

// The planar viewport: centred at the origin, wide enough for every finite point of the scene
// (points at infinity sit on the Ω ring whatever the width).
dr::PlaneView fit_plane(const t2::Scene& s) {
  double r = 0;
  auto see = [&](const t2::Point& p) {
    if (p.w() == 0) return;
    const double d = std::hypot(p.x() / p.w(), p.y() / p.w());
    if (std::isfinite(d)) r = std::max(r, d);
  };
  for (const auto& p : s.points) see(p.point);
  for (const auto& g : s.segments) {
    see(g.a.point);
    see(g.b.point);
  }
  for (const auto& g : s.polygons)
    for (const auto& v : g.vertices) see(v.point);
  for (const auto& g : s.lines) {
    see(g.a.point);
    see(g.b.point);
  }
  for (const auto& g : s.circles) {
    // A finite or beyond-infinity circle reaches |C| + |P − C| from the origin.
    const t2::Point &c = g.center.point, &p = g.through.point;
    if (c.w() == 0 || p.w() == 0) {
      see(c);
      see(p);
      continue;
    }
    const double cx = c.x() / c.w(), cy = c.y() / c.w();
    const double far = std::hypot(cx, cy) + std::hypot(p.x() / p.w() - cx, p.y() / p.w() - cy);
    if (std::isfinite(far)) r = std::max(r, far);
  }
  dr::PlaneView v;
  v.half_width = std::max(1.0, 1.2 * r);
  return v;
}

int run(Args args) {
  std::optional<std::string> file, output, format_name;
  Model model = Model::both;
  dr::SphereView sphere;
  for (std::size_t i = 0; i < args.size(); ++i) {
    const std::string& a = args[i];
    auto value = [&]() -> const std::string& {
      if (i + 1 == args.size()) throw UsageError(fmt::format("{} needs a value", a));
      return args[++i];
    };
    if (a == "-o") {
      output = value();
    } else if (a == "--model") {
      model = parse_model(value());
    } else if (a == "--format") {
      format_name = value();
    } else if (a == "--view") {
      const std::string& v = value();
      const auto comma = v.find(',');
      if (comma == std::string::npos) throw UsageError(fmt::format("--view takes LAT,LON, not '{}'", v));
      sphere.lat = parse_degrees(v.substr(0, comma), "LAT", 90);
      sphere.lon = parse_degrees(v.substr(comma + 1), "LON", 360);
    } else if (a.size() > 1 && a[0] == '-') {
      throw UsageError(fmt::format("unknown option '{}'", a));
    } else if (file) {
      throw UsageError("give exactly one scene file");
    } else {
      file = a;
    }
  }
  if (!file) throw UsageError("give a scene file");
  if (!output) throw UsageError("give the output file with -o OUT");
  // The format first: a bad extension must not cost a parse, and must not leave a file.
  const dr::Format fmt = format_name ? parse_format(*format_name) : dr::format_of(*output);
  const t2::Scene scene = t2::read_scene(*file);  // ParseError: file:line: message, exit 2
  const dr::Figure fig = dr::figure_of(scene);
  const dr::PlaneView plane = fit_plane(scene);
  std::string bytes;
  switch (model) {
    case Model::plane: bytes = dr::render(fig, plane, fmt); break;
    case Model::sphere: bytes = dr::render(fig, sphere, fmt); break;
    case Model::both: bytes = dr::render_both(fig, plane, sphere, fmt); break;
  }
  t2::write_file_atomically(*output, bytes);
  return kOk;
}

}  // namespace

T2_COMMAND({"draw", "draw a scene file in the planar model, the spherical model, or both",
            "Usage: t2 draw FILE [--model plane|sphere|both] [--view LAT,LON] [--format svg|png|pdf] -o OUT\n"
            "\n"
            "Reads the scene file FILE (the format is described in the README, section \"Scene\n"
            "files\") and draws its points (with their labels), segments (blue), polygons\n"
            "(green), lines (grey, arrow: orientation) and circles (red: finite, beyond infinity\n"
            "on the other side, or infinite: a line or Ω), following the conventions of the\n"
            "figures: front side solid with filled\n"
            "markers, back side dashed with hollow markers, Ω a grey ring (planar model) or the\n"
            "equator (spherical model).\n"
            "\n"
            "  --model M        plane, sphere or both side by side (default both)\n"
            "  --view LAT,LON   direction from which the sphere is seen, degrees (default 25,-65)\n"
            "  --format F       svg, png or pdf (default: from the extension of OUT)\n"
            "  -o OUT           the picture; written atomically, only when everything succeeded\n"
            "\n"
            "The planar view is centred at the origin and wide enough for every finite point\n"
            "and every circle of finite radius.\n"
            "\n"
            "Exit status: 0 done; 2 bad usage, unreadable file or invalid scene (the message\n"
            "reads file:line: what is wrong; no output file is created).\n",
            run});

}  // namespace t2cli
