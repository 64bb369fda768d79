// t2 info: what a scene file holds, point by point.
#include <fmt/format.h>

#include <cmath>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "command.hpp"
#include "scene_argument.hpp"
#include "t2/kernel/io.hpp"
#include "t2/kernel/orient.hpp"
#include "t2/kernel/scene.hpp"

namespace t2cli {
namespace cmd_info {

// x/w or y/w may overflow a double for a valid point (w = 1e-300, x = 1e300): say so.
constexpr const char* kOverflow = "(overflows double)";

std::string cartesian(const t2::Point& p) {
  const auto c = t2::to_cartesian(p);
  if (!c) return "-";
  if (!std::isfinite(c->first) || !std::isfinite(c->second)) return kOverflow;
  return fmt::format("({}, {})", t2::to_string(c->first), t2::to_string(c->second));
}

std::string normalized_text(const t2::Point& p) {
  try {
    return t2::to_string(t2::normalized(p));
  } catch (const t2::BadInput&) {  // t2::normalized refuses a ratio that overflows
    return kOverflow;
  }
}

// The name of the i-th point (0-based) in messages: its label, or #k (1-based).
std::string name_of(const t2::ScenePoint& p, std::size_t i) {
  return p.label.empty() ? fmt::format("#{}", i + 1) : p.label;
}

const char* sign_text(t2::Sign s) { return s > 0 ? "+1" : (s < 0 ? "-1" : "0"); }

std::string plural(std::size_t n, const char* word) {
  return fmt::format("{} {}{}", n, word, n == 1 ? "" : "s");
}

std::string report(const t2::Scene& s, bool pairs) {
  std::string out = fmt::format("{}: {}, {}, {}", s.name, plural(s.points.size(), "point"),
                                plural(s.segments.size(), "segment"), plural(s.polygons.size(), "polygon"));
  if (!s.lines.empty()) out += ", " + plural(s.lines.size(), "line");
  if (!s.circles.empty()) out += ", " + plural(s.circles.size(), "circle");
  out += "\n";
  if (!s.points.empty()) {
    out += fmt::format("{:<6} {:<6} {:<8} {:<9} {:<36} {}\n", "point", "line", "label", "side",
                       "normalized [w, x, y]", "cartesian (x/w, y/w)");
    for (std::size_t i = 0; i < s.points.size(); ++i) {
      const auto& p = s.points[i];
      out += fmt::format("{:<6} {:<6} {:<8} {:<9} {:<36} {}\n", fmt::format("#{}", i + 1), p.line,
                         p.label.empty() ? "-" : p.label, t2::to_string(t2::side_of(p.point)),
                         normalized_text(p.point), cartesian(p.point));
    }
  }
  for (const auto& g : s.segments)
    out += fmt::format("segment (line {}): {} {} to {} {}\n", g.line, t2::to_string(t2::side_of(g.a.point)),
                       t2::to_string(g.a.point), t2::to_string(t2::side_of(g.b.point)), t2::to_string(g.b.point));
  for (const auto& g : s.polygons) {
    std::size_t count[3] = {0, 0, 0};
    for (const auto& v : g.vertices) ++count[static_cast<int>(t2::side_of(v.point)) + 1];
    out += fmt::format("polygon (line {}): {} ({} front, {} at infinity, {} back)\n", g.line,
                       fmt::format("{} vert{}", g.vertices.size(), g.vertices.size() == 1 ? "ex" : "ices"), count[2], count[1], count[0]);
  }
  for (const auto& g : s.lines) out += fmt::format("line (line {}): {}\n", g.line, t2::to_string(g.join()));
  for (const auto& g : s.circles)
    out += fmt::format("circle (line {}): {}, radius {}\n", g.line, t2::to_string(g.circle()),
                       t2::to_string(t2::radius_kind(g.circle())));
  if (pairs) {
    if (s.points.size() < 3) out += "orient: fewer than 3 points, no triples\n";
    for (std::size_t i = 0; i + 2 < s.points.size(); ++i) {
      const auto& a = s.points[i];
      const auto& b = s.points[i + 1];
      const auto& c = s.points[i + 2];
      out += fmt::format("orient({}, {}, {}) = {}   (lines {}, {}, {})\n", name_of(a, i), name_of(b, i + 1),
                         name_of(c, i + 2), sign_text(t2::orient(a.point, b.point, c.point)), a.line,
                         b.line, c.line);
    }
  }
  return out;
}

struct Options {
  std::string file;
  std::optional<std::string> output;
  bool pairs = false;
};

int info(const Options& o) {
  const t2::Scene scene = read_scene_argument(o.file);
  const std::string out = report(scene, o.pairs);
  if (o.output)
    t2::write_file_atomically(*o.output, out);
  else
    fmt::print("{}", out);
  return kOk;
}

Action setup(Arguments& app) {
  auto o = std::make_shared<Options>();
  app.description(
      "Reads the scene file FILE (- for standard input; the format is described in the\n"
      "README, section \"Scene files\") and prints, for each point outside blocks, its side\n"
      "of T2 (front w>0, back w<0, infinity w=0), its normalized coordinates (a positive\n"
      "rescaling: w = +1 or -1, or max(|x|,|y|) = 1 at infinity) and its Cartesian\n"
      "coordinates (x/w, y/w) where defined; then one line per segment and polygon.");
  app.add_option("FILE", o->file, "the scene file, - for standard input")->required();
  app.add_flag("--pairs", o->pairs,
               "also print orient(p, q, r) (+1, 0, -1, exact) of every three consecutive\npoints");
  app.add_option("-o", o->output, "write the report to OUT (atomically) instead of standard output")
      ->type_name("OUT");
  app.footer(
      "Exit status: 0 done; 2 bad usage, unreadable file or invalid scene (the message\n"
      "reads file:line: what is wrong).");
  return [o] { return info(*o); };
}

}  // namespace cmd_info

T2_COMMAND({"info", "what a scene file holds: sides, coordinates, orientations", cmd_info::setup});

}  // namespace t2cli
