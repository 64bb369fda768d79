#pragma once
// Shared helpers of the animation tests: a triangulation's finite faces in the form a recorded
// step holds them, sorted, so that a step's picture and an answer compare as sets; and the steps
// of a page of `t2 animate`, decoded here apart from the player (its edit scripts applied by
// this file's own `patched`, its data decoded by this file's own `unpacked`).
#include <algorithm>
#include <array>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>
#include <zlib.h>

#include "t2/trace/step.hpp"
#include "t2/triangulation/triangulation.hpp"

namespace t2::testing {

/// The finite triangles of `t` as trace triples (each counter-clockwise, as the structure
/// lists it), in increasing order.
inline std::vector<trace::Tri> sorted_triangles(const Triangulation& t) {
  std::vector<trace::Tri> out;
  for (const auto& f : t.finite_triangles()) out.push_back({f[0], f[1], f[2]});
  std::sort(out.begin(), out.end());
  return out;
}

/// The sequence `old` edited by e, {"f": whole} or {"d": [copy, skip, count, elements..., ...]}
/// (tools/t2/animate/delta.hpp).
inline nlohmann::json patched(const nlohmann::json& old, const nlohmann::json& e) {
  if (e.contains("f")) return e["f"];
  const nlohmann::json& d = e.at("d");
  nlohmann::json out = nlohmann::json::array();
  std::size_t i = 0, k = 0;
  while (k < d.size()) {
    const std::size_t copy = d[k++], skip = d[k++], count = d[k++];
    for (std::size_t j = 0; j < copy; ++j) out.push_back(old.at(i++));
    i += skip;
    for (std::size_t j = 0; j < count; ++j) out.push_back(d.at(k++));
  }
  for (; i < old.size(); ++i) out.push_back(old[i]);
  return out;
}

/// The page's data as page.cpp stores it, base64 (RFC 4648) of zlib-deflated text, decoded: the
/// base64 digits by their table, the rest by zlib's `uncompress` into a buffer grown until it fits.
inline std::string unpacked(const std::string& base64) {
  const std::string digits = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::vector<unsigned char> bytes;
  unsigned bits = 0;
  int have = 0;
  for (char c : base64) {
    if (c == '=' || c == '\n' || c == ' ') continue;
    const auto d = digits.find(c);
    if (d == std::string::npos) throw std::runtime_error("the page's data is not base64");
    bits = (bits << 6 | static_cast<unsigned>(d)) & 0xffffff;
    if ((have += 6) >= 8) bytes.push_back(static_cast<unsigned char>(bits >> (have -= 8)));
  }
  for (uLongf size = 8 * bytes.size() + 1024;; size *= 2) {
    std::string out(size, '\0');
    uLongf got = size;
    const int rc = uncompress(reinterpret_cast<Bytef*>(out.data()), &got, bytes.data(), bytes.size());
    if (rc == Z_OK) return out.substr(0, got);
    if (rc != Z_BUF_ERROR) throw std::runtime_error("the page's data does not inflate");
  }
}

/// One step of a page: its JSON, its frame's SVG, its triangles and its edges in focus, rebuilt.
struct PageStep {
  nlohmann::json step;                          ///< the step as the page holds it
  std::string svg;                              ///< the frame, its lines joined
  std::vector<std::array<std::size_t, 3>> triangles;  ///< every finite triangle so far
  std::vector<std::array<std::size_t, 2>> edges;      ///< the edges in focus
};

/// The data of a page of `t2 animate` as the JSON text that the page packed.
inline std::string page_data(const std::string& html) {
  const std::string open = "<script type=\"application/octet-stream\" id=\"t2-data\">";
  const auto at = html.find(open);
  const auto end = html.find("</script>", at);
  if (at == std::string::npos || end == std::string::npos) throw std::runtime_error("no data in the page");
  return unpacked(html.substr(at + open.size(), end - at - open.size()));
}

/// The steps of a page of `t2 animate`, in order.
inline std::vector<PageStep> page_steps(const std::string& html) {
  const nlohmann::json data = nlohmann::json::parse(page_data(html));
  std::vector<std::string> style;  // class k of the frames' style sheet: ".fk{style}" per line
  std::istringstream css(data.value("css", std::string()));
  for (std::string rule; std::getline(css, rule);) {
    const std::size_t brace = rule.find('{'), k = std::stoul(rule.substr(2, brace - 2));
    if (style.size() <= k) style.resize(k + 1);
    style[k] = rule.substr(brace + 1, rule.size() - brace - 2);
  }
  std::vector<PageStep> out;
  nlohmann::json frame = nlohmann::json::array(), tris = nlohmann::json::array(), chain = nlohmann::json::array(),
                 edges = nlohmann::json::array();
  const bool of_segments = data.value("segments", false);  // its chains are edits too
  for (const auto& s : data.at("steps")) {
    frame = patched(frame, s.at("frame"));
    tris = patched(tris, s.at("triangles"));
    edges = patched(edges, s.at("edges"));
    PageStep p{s, "", {}, {}};
    if (of_segments) p.step["chain"] = chain = patched(chain, s.at("chain"));
    for (const auto& i : frame) {  // each line with its style written out again
      std::string line = data.at("lines").at(i.get<std::size_t>()).get<std::string>();
      if (const auto at = line.find(" class=\"f"); at != std::string::npos) {
        const auto end = line.find('"', at + 9);
        line.replace(at, end + 1 - at, " style=\"" + style.at(std::stoul(line.substr(at + 9, end - at - 9))) + "\"");
      }
      p.svg += line + "\n";
    }
    for (const auto& t : tris) p.triangles.push_back({t[0], t[1], t[2]});
    for (const auto& e : edges) p.edges.push_back({e[0], e[1]});
    out.push_back(std::move(p));
  }
  return out;
}

}  // namespace t2::testing
