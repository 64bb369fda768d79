// The text `t2 gen` writes (generate.hpp): a comment with the command, then the scene.
#include <fmt/format.h>

#include "t2/gen/generate.hpp"
#include "t2/kernel/number.hpp"

namespace t2::gen {

namespace {

std::string point_line(const Point& p) {
  if (p.w() == 1) return fmt::format("{} {}", to_string(p.x()), to_string(p.y()));
  return fmt::format("{} {} {}", to_string(p.w()), to_string(p.x()), to_string(p.y()));
}

std::string command(Kind k, const Options& o) {
  std::string c = fmt::format("# t2 gen {} --n {} --seed {}", name(k), o.n, o.seed);
  if (k == Kind::both_sides) c += fmt::format(" --back {}", to_string(o.back));
  if (k == Kind::segments) c += fmt::format(" --crossings {}", o.crossings);
  if (k == Kind::normal) c += fmt::format(" --clusters {}", o.clusters);
  if (k == Kind::circle && o.cartesian) c += " --cartesian";
  if (k == Kind::simple_polygon && o.untangle) c += " --untangle";
  return c + "\n# " + std::string(description(k)) + "\n";
}

}  // namespace

std::string to_text(Kind k, const Options& o) {
  std::string out = command(k, o);
  switch (k) {
    case Kind::cube:
    case Kind::sphere:
      for (const auto& p : points3(k, o))
        out += fmt::format("{} {} {}\n", to_string(p[0]), to_string(p[1]), to_string(p[2]));
      return out;
    case Kind::simple_polygon:
    case Kind::star_polygon:
    case Kind::convex_polygon:
    case Kind::monotone_polygon:
      out += "polygon\n";
      for (const auto& p : polygon(k, o)) out += "  " + point_line(p) + "\n";
      return out + "end\n";
    case Kind::segments:
    case Kind::polygon_edges:
    case Kind::segment_grid:
    case Kind::segments_through_point:
      for (const auto& s : segments(k, o))
        out += fmt::format("segment\n  {}\n  {}\nend\n", point_line(s.source()), point_line(s.target()));
      return out;
    default:
      for (const auto& p : points(k, o)) out += point_line(p) + "\n";
      return out;
  }
}

}  // namespace t2::gen
