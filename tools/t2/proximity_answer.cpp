// The answers of the proximity commands (proximity_answer.hpp).
#include "proximity_answer.hpp"

#include <fmt/format.h>

namespace t2cli {

void print_pairs(const AnswerDrawing& d, const t2::Scene& scene, const std::vector<t2::Point>& P,
                 const std::vector<std::pair<std::uint32_t, std::uint32_t>>& pairs, const std::string& header) {
  t2::Scene s;
  const t2::SceneStyle red = style_of("color=red width=2 layer=1");
  std::string out;
  for (auto [i, j] : pairs) {
    out += fmt::format("{} {}\n", i, j);
    if (!(P[i] == P[j]) && !(P[i] == t2::antipode(P[j])))
      s.segments.push_back(t2::SceneSegment{scene_point(P[i]), scene_point(P[j]), 0, red});
  }
  write_answer(d, scene, std::move(s), header);
  fmt::print("{}", out);
}

void print_circle(const AnswerDrawing& d, const t2::Scene& scene, const std::vector<t2::Point>& P,
                  const t2::ExactPoint& centre, const std::vector<std::uint32_t>& on_circle, const std::string& header) {
  std::string out = fmt::format("{} {} {}\n", centre.w().get_str(), centre.x().get_str(), centre.y().get_str());
  for (std::size_t k = 0; k < on_circle.size(); ++k) out += fmt::format("{}{}", k ? " " : "", on_circle[k]);
  out += "\n";
  t2::Scene s;
  const t2::Point z = t2::to_double(centre);
  if (!on_circle.empty() && !(P[on_circle[0]] == z))
    s.circles.push_back(
        t2::SceneCircle{scene_point(z), scene_point(P[on_circle[0]]), 0, style_of("color=red width=2 layer=1")});
  s.points.push_back(scene_point(z, style_of("color=red layer=1")));
  write_answer(d, scene, std::move(s), header);
  fmt::print("{}", out);
}

t2::Undefined undefined_at(const t2::Scene& scene, std::uint32_t site, std::uint32_t other, const std::string& what) {
  const int line = scene.points[site].line, second = scene.points[other].line;
  return t2::Undefined(site == other ? fmt::format("{}:{}: {}", scene.name, line, what)
                                     : fmt::format("{}:{} and line {}: {}", scene.name, line, second, what));
}

}  // namespace t2cli
