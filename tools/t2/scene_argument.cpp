#include "scene_argument.hpp"

#include <iostream>
#include <iterator>

namespace t2cli {

t2::Scene read_scene_argument(const std::string& file) {
  if (file != "-") return t2::read_scene(file);
  const std::string text((std::istreambuf_iterator<char>(std::cin)), std::istreambuf_iterator<char>());
  return t2::parse_scene(text, "<stdin>");
}

std::vector<t2::Point> scene_points(const t2::Scene& s) {
  std::vector<t2::Point> P;
  P.reserve(s.points.size());
  for (const auto& p : s.points) P.push_back(p.point);
  return P;
}

}  // namespace t2cli
