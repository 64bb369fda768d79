// The page of `t2 animate` (page.hpp).
#include "animate/page.hpp"

#include <fmt/format.h>

#include <nlohmann/json.hpp>
#include <algorithm>
#include <map>
#include <stdexcept>
#include <string_view>

#include "animate/frame.hpp"
#include "animate/player_html.hpp"

namespace t2cli::animate {
namespace {

// Text put inside an HTML element: &, < and > escaped.
std::string escape(std::string_view s) {
  std::string out;
  for (char c : s) {
    if (c == '&') out += "&amp;";
    else if (c == '<') out += "&lt;";
    else if (c == '>') out += "&gt;";
    else out += c;
  }
  return out;
}

void replace(std::string& text, std::string_view marker, const std::string& by) {
  const auto at = text.find(marker);
  if (at == std::string::npos) throw std::logic_error(fmt::format("player.html lacks the marker {}", marker));
  text.replace(at, marker.size(), by);
}

nlohmann::json to_json(const t2::trace::Step& s) {
  return {{"kind", s.kind},          {"depth", static_cast<int>(s.depth)},
          {"text", s.text},          {"structure", s.structure},
          {"chain", s.chain},        {"closed", s.closed},
          {"triangles", s.triangles}, {"points", s.points},
          {"edges", s.edges},        {"touched", s.touched},
          {"circle", s.circle}};
}

}  // namespace

std::string page(const std::string& title, const std::vector<t2::Point>& P, const std::vector<t2::trace::Step>& steps) {
  std::string html(reinterpret_cast<const char*>(player_html), player_html_size);
  // The frames share most of their lines (the Ω ring, the sphere, the glyphs, the points): each
  // distinct line of SVG is stored once, and a frame is the list of its lines' numbers.
  std::map<std::string, std::size_t, std::less<>> number;
  nlohmann::json lines = nlohmann::json::array();
  nlohmann::json data = {{"title", title}, {"steps", nlohmann::json::array()}};
  for (const auto& s : steps) {
    nlohmann::json j = to_json(s);
    const std::string svg = frame_svg(P, s);
    std::vector<std::size_t> frame;
    for (std::size_t at = 0; at < svg.size();) {
      const std::size_t end = std::min(svg.find('\n', at), svg.size());
      const std::string_view line(svg.data() + at, end - at);
      auto it = number.find(line);
      if (it == number.end()) {
        it = number.emplace(std::string(line), lines.size()).first;
        lines.push_back(it->first);
      }
      frame.push_back(it->second);
      at = end + 1;
    }
    j["frame"] = frame;
    data["steps"].push_back(std::move(j));
  }
  data["lines"] = std::move(lines);
  std::string json = data.dump();
  for (auto at = json.find('<'); at != std::string::npos; at = json.find('<', at))  // no "</script" nor "<!--"
    json.replace(at, 1, "\\u003c");
  const std::string t = escape(title);
  replace(html, "<!--T2_TITLE-->", t);
  replace(html, "<!--T2_TITLE-->", t);
  replace(html, "/*T2_DATA*/", json);
  return html;
}

}  // namespace t2cli::animate
