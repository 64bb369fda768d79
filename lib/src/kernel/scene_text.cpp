// A scene as the text of a scene file (see t2/kernel/scene.hpp, to_string).
#include <fmt/format.h>

#include <initializer_list>

#include "t2/kernel/number.hpp"
#include "t2/kernel/scene.hpp"

namespace t2 {

namespace {

// "x y" for a point with w = 1, else "w x y": numbers that read back to the same doubles.
std::string coordinates(const Point& p) {
  if (p.w() == 1) return fmt::format("{} {}", to_string(p.x()), to_string(p.y()));
  return fmt::format("{} {} {}", to_string(p.w()), to_string(p.x()), to_string(p.y()));
}

void block(std::string& out, std::string_view keyword, const SceneStyle& style,
           std::initializer_list<const ScenePoint*> points) {
  out += fmt::format("{}{}\n", keyword, to_attributes(style));
  for (const ScenePoint* p : points) out += fmt::format("  {}\n", coordinates(p->point));
  out += "end\n";
}

}  // namespace

std::string to_string(const Scene& s) {
  std::string out;
  for (const auto& p : s.points) {
    if (!p.label.empty()) out += fmt::format("label {} ", p.label);
    out += fmt::format("{}{}\n", coordinates(p.point), to_attributes(p.style));
  }
  for (const auto& g : s.segments) block(out, "segment", g.style, {&g.a, &g.b});
  for (const auto& g : s.polygons) {
    out += fmt::format("polygon{}\n", to_attributes(g.style));
    for (const auto& v : g.vertices) out += fmt::format("  {}\n", coordinates(v.point));
    out += "end\n";
  }
  for (const auto& g : s.lines) block(out, "line", g.style, {&g.a, &g.b});
  for (const auto& g : s.circles) block(out, "circle", g.style, {&g.center, &g.through});
  return out;
}

}  // namespace t2
