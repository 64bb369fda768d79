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

}  // namespace t2cli
