// The page of `t2 animate` (page.hpp).
#include "animate/page.hpp"

#include <fmt/format.h>

#include <nlohmann/json.hpp>
#include <zlib.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <charconv>
#include <cmath>
#include <map>
#include <stdexcept>
#include <string_view>
#include <unordered_map>

#include "animate/delta.hpp"
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
  nlohmann::json j = {{"kind", s.kind},   {"depth", static_cast<int>(s.depth)},
                      {"text", s.text},   {"structure", s.structure},
                      {"chain", s.chain}, {"closed", s.closed},
                      {"points", s.points}, {"touched", s.touched}};
  if (!s.entries.empty()) j["entries"] = s.entries;  // only the steps that have them
  return j;
}

// A step's sequence `now` as the edit script from `before` (delta.hpp), when that is shorter than
// `now` itself: {"d": script}; else {"f": now}.
template <class T>
nlohmann::json encoded(const std::vector<T>& before, const std::vector<T>& now) {
  if (const auto groups = edit_script(before, now, now.size() / 2 + 8)) {
    nlohmann::json d = nlohmann::json::array();
    for (const EditGroup& g : *groups) {
      d.push_back(g.copy);
      d.push_back(g.skip);
      d.push_back(g.count);
      for (std::size_t k = g.from; k < g.from + g.count; ++k) d.push_back(now[k]);
    }
    return {{"d", std::move(d)}};
  }
  return {{"f", now}};
}

// Douglas–Peucker on pixel positions: the points of [a, b] that keep the polyline within `tol`
// pixels of the original, marked in `keep`.
void simplify(const std::vector<std::array<double, 2>>& p, std::size_t a, std::size_t b, double tol,
              std::vector<bool>& keep) {
  if (b <= a + 1) return;
  const double dx = p[b][0] - p[a][0], dy = p[b][1] - p[a][1], len = std::hypot(dx, dy);
  std::size_t far = a;
  double most = -1;
  for (std::size_t k = a + 1; k < b; ++k) {
    const double ex = p[k][0] - p[a][0], ey = p[k][1] - p[a][1];
    const double d = len > 0 ? std::abs(ex * dy - ey * dx) / len : std::hypot(ex, ey);
    if (d > most) most = d, far = k;
  }
  if (most <= tol) return;
  keep[far] = true;
  simplify(p, a, far, tol, keep);
  simplify(p, far, b, tol, keep);
}

// A number of a path in pixels, to 0.1 px ("12.5", "-3", "0").
std::string px(double v) {
  std::string t = fmt::format("{:.1f}", v);
  if (t.ends_with(".0")) t.resize(t.size() - 2);
  return t == "-0" ? "0" : t;
}

// The words of path data as Cairo writes it ("M 12.515625 3 L ..."), split at spaces; numbers
// are read by std::from_chars (an istringstream took a fifth of the time of a page).
class PathWords {
 public:
  explicit PathWords(std::string_view d) : d_(d) {}
  /// The next word into w; false at the end.
  bool next(std::string_view& w) {
    while (at_ < d_.size() && d_[at_] == ' ') ++at_;
    if (at_ == d_.size()) return false;
    const std::size_t end = std::min(d_.find(' ', at_), d_.size());
    w = d_.substr(at_, end - at_);
    at_ = end;
    return true;
  }
  /// The next word as a number (0 when there is none or it is no number).
  double number() {
    std::string_view w;
    return next(w) ? number_of(w) : 0;
  }
  /// The word w as a number (0 when it is no number).
  static double number_of(std::string_view w) {
    double v = 0;
    std::from_chars(w.data(), w.data() + w.size(), v);
    return v;
  }

 private:
  std::string_view d_;
  std::size_t at_ = 0;
};

// Path data with every number written to 0.1 px (the curves of the labels' glyphs and of the
// circles, which Cairo writes to 6 decimals): "M 12.515625 3 C ..." becomes "M12.5 3C...".
std::string rounded_path(std::string_view d) {
  std::string out;
  PathWords words(d);
  std::string_view w;
  bool after_number = false;
  while (words.next(w)) {
    if (std::isalpha(static_cast<unsigned char>(w[0]))) {
      out += w;
      after_number = false;
    } else {
      if (after_number) out += ' ';
      out += px(PathWords::number_of(w));
      after_number = true;
    }
  }
  return out;
}

// The path data d made lighter. Straight pieces only (M, L, Z): each piece simplified to 0.25 px
// (Douglas–Peucker) and written to 0.1 px. With curves (C): every number written to 0.1 px. A
// picture's pixels, not geometry: the page is scaled to the screen, where a quarter pixel does
// not show.
std::string lighter_path(std::string_view d) {
  if (d.find_first_not_of("MLZC0123456789.-+e ") != std::string_view::npos) return std::string(d);
  if (d.find('C') != std::string_view::npos) return rounded_path(d);
  std::string out;
  std::vector<std::array<double, 2>> run;
  auto flush = [&] {
    if (run.empty()) return;
    std::vector<bool> keep(run.size(), false);
    keep.front() = keep.back() = true;
    simplify(run, 0, run.size() - 1, 0.25, keep);
    for (std::size_t k = 0; k < run.size(); ++k)
      if (keep[k]) out += (k == 0 ? "M" : "L") + px(run[k][0]) + " " + px(run[k][1]);
    run.clear();
  };
  PathWords words(d);
  std::string_view cmd;
  while (words.next(cmd)) {
    if (cmd == "Z") {
      flush();
      out += "Z";
    } else {
      if (cmd == "M") flush();
      const double x = words.number(), y = words.number();
      run.push_back({x, y});
    }
  }
  flush();
  return out;
}

// A line of a frame made lighter: its style attribute replaced by a class of the page's style
// sheet (`classes`: style -> number), its path data by `lighter_path`.
std::string lighter(std::string_view line, std::map<std::string, std::size_t, std::less<>>& classes) {
  std::string out(line);
  if (const auto at = out.find(" style=\""); at != std::string::npos) {
    const auto end = out.find('"', at + 8);
    const std::string style = out.substr(at + 8, end - at - 8);
    const auto it = classes.emplace(style, classes.size()).first;
    out.replace(at, end + 1 - at, fmt::format(" class=\"f{}\"", it->second));
  }
  if (const auto at = out.find(" d=\""); at != std::string::npos) {
    const auto end = out.find('"', at + 4);
    out.replace(at + 4, end - at - 4, lighter_path(std::string_view(out).substr(at + 4, end - at - 4)));
  }
  return out;
}

// The page's data deflated (zlib's format, at its best compression: the same text gives the same
// bytes, so a page is as deterministic as its frames) and written in base64 (RFC 4648), which the
// player inflates with the browser's DecompressionStream. The SVG lines of the frames repeat
// their commands, classes and digits: at 200 points a Delaunay page's data shrinks about fivefold.
std::string packed(const std::string& text) {
  uLongf size = compressBound(text.size());
  std::vector<unsigned char> z(size);
  if (compress2(z.data(), &size, reinterpret_cast<const Bytef*>(text.data()), text.size(), Z_BEST_COMPRESSION) != Z_OK)
    throw std::runtime_error("zlib could not deflate the page's data");
  static constexpr char digit[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  out.reserve((size + 2) / 3 * 4);
  for (uLongf k = 0; k < size; k += 3) {
    const unsigned v = z[k] << 16 | (k + 1 < size ? z[k + 1] << 8 : 0) | (k + 2 < size ? z[k + 2] : 0);
    out += digit[v >> 18 & 63];
    out += digit[v >> 12 & 63];
    out += k + 1 < size ? digit[v >> 6 & 63] : '=';
    out += k + 2 < size ? digit[v & 63] : '=';
  }
  return out;
}

}  // namespace

std::string page(const std::string& title, const std::vector<t2::Point>& P, const std::vector<t2::trace::Step>& steps,
                 const std::vector<t2::trace::Edge>& segments) {
  std::string html(reinterpret_cast<const char*>(player_html), player_html_size);
  // The frames share most of their lines (the Ω ring, the sphere, the glyphs, the points): each
  // distinct line of SVG is stored once, and a frame is the list of its lines' numbers. A step
  // changes little: its frame, its triangles and its edges are stored as the edit from the step before
  // (delta.hpp), which the player applies.
  // (`number` is hashed: a search tree compared long lines that share their first hundred
  // characters, a fifth of the page's time.)
  std::unordered_map<std::string, std::size_t> number;
  std::map<std::string, std::size_t, std::less<>> classes;
  nlohmann::json lines = nlohmann::json::array();
  nlohmann::json data = {{"title", title}, {"steps", nlohmann::json::array()}, {"segments", !segments.empty()}};
  std::vector<std::size_t> previous;
  std::vector<t2::trace::Tri> previous_triangles;
  std::vector<std::size_t> previous_chain;  // a page of segments: the status, stored as edits too
  std::vector<t2::trace::Edge> previous_edges;  // a spanning tree grows an edge a step: edited too
  for (const auto& s : steps) {
    nlohmann::json j = to_json(s);
    const std::string svg = frame_svg(P, s, segments);
    std::vector<std::size_t> frame;
    for (std::size_t at = 0; at < svg.size();) {
      const std::size_t end = std::min(svg.find('\n', at), svg.size());
      const std::string line = lighter(std::string_view(svg.data() + at, end - at), classes);
      auto it = number.find(line);
      if (it == number.end()) {
        it = number.emplace(line, lines.size()).first;
        lines.push_back(it->first);
      }
      frame.push_back(it->second);
      at = end + 1;
    }
    j["frame"] = encoded(previous, frame);
    j["triangles"] = encoded(previous_triangles, s.triangles);
    if (!segments.empty()) {
      j["chain"] = encoded(previous_chain, s.chain);
      previous_chain = s.chain;
    }
    j["edges"] = encoded(previous_edges, s.edges);
    previous = std::move(frame);
    previous_triangles = s.triangles;
    previous_edges = s.edges;
    data["steps"].push_back(std::move(j));
  }
  data["lines"] = std::move(lines);
  std::string css;  // the frames' styles, one class each (`lighter`)
  for (const auto& [style, k] : classes) css += fmt::format(".f{}{{{}}}\n", k, style);
  data["css"] = css;
  const std::string t = escape(title);
  replace(html, "<!--T2_TITLE-->", t);
  replace(html, "<!--T2_TITLE-->", t);
  replace(html, "/*T2_DATA*/", packed(data.dump()));
  return html;
}

}  // namespace t2cli::animate
