#include "t2/kernel/scene.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <charconv>
#include <climits>
#include <cmath>
#include <cstdlib>
#include <optional>
#include <system_error>
#include <unordered_map>
#include <utility>

#include "t2/kernel/io.hpp"

namespace t2 {

ParseError::ParseError(std::string file, int line, const std::string& message)
    : BadInput(fmt::format("{}:{}: {}", file, line, message)),
      file_(std::move(file)),
      line_(line),
      message_(message) {}

const ScenePoint* Scene::find(std::string_view label) const {
  for (const auto& p : points)
    if (!p.label.empty() && p.label == label) return &p;
  return nullptr;
}

namespace {

bool is_space(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v'; }
bool is_letter(char c) { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_'; }
bool is_digit(char c) { return c >= '0' && c <= '9'; }

// A token for a message: quoted, at most 32 bytes, unprintable bytes as \xNN.
std::string quote(std::string_view t) {
  std::string s = "'";
  const std::size_t n = std::min<std::size_t>(t.size(), 32);
  for (std::size_t i = 0; i < n; ++i) {
    const auto c = static_cast<unsigned char>(t[i]);
    if (c < 0x20 || c >= 0x7f || c == '\\')
      s += fmt::format("\\x{:02x}", c);
    else
      s += static_cast<char>(c);
  }
  if (t.size() > n) s += "...";
  return s + "'";
}

// A label: a letter or '_', then letters, digits, '_' and "'" (so p' and q'' are names).
bool is_name(std::string_view w) {
  if (w.empty() || !is_letter(w[0])) return false;
  for (char c : w)
    if (!is_letter(c) && !is_digit(c) && c != '\'') return false;
  return true;
}

// Words that from_chars reads, whole, as a non-finite value: "inf", "-nan", "Infinity" ...
bool is_non_finite_number(std::string_view w) {
  if (w.size() > 1 && w[0] == '+') w.remove_prefix(1);
  double v = 0;
  const auto r = std::from_chars(w.data(), w.data() + w.size(), v);
  return r.ec == std::errc() && r.ptr == w.data() + w.size() && !std::isfinite(v);
}

// A word of the form key=value: a style attribute (scene_style.hpp).
bool is_attribute(std::string_view w) { return w.find('=') != std::string_view::npos; }

// ---------------------------------------------------------------- block kinds
// Each kind of block is one row of kBlockKinds: its keyword, how many points it holds, and the
// builder that checks the block is defined and adds it to the scene. Adding a kind of block
// is adding a member to Scene, a builder and a row here (and its drawing, in
// t2/draw/scene_figure.cpp); the parser and its messages follow the table.

void check_edge(const Scene& s, const ScenePoint& p, const ScenePoint& q, int line, const std::string& what) {
  if (q.point == antipode(p.point))
    throw ParseError(s.name, line,
                     fmt::format("{}: segment(p, q) is undefined when q = antipode(p); here p = {} "
                                 "(line {}) and q = {} (line {})",
                                 what, to_string(p.point), p.line, to_string(q.point), q.line));
}

// The builders: `v` holds as many points as the row says; `line` is the line of the block's
// keyword, `end` the line of its 'end'.
void build_segment(Scene& s, std::vector<ScenePoint>&& v, int line, int /*end*/, SceneStyle&& st) {
  check_edge(s, v[0], v[1], v[1].line, "segment");
  s.segments.push_back(SceneSegment{v[0], v[1], line, std::move(st)});
}

void build_polygon(Scene& s, std::vector<ScenePoint>&& v, int line, int end, SceneStyle&& st) {
  const std::size_t n = v.size();
  for (std::size_t i = 1; i < n; ++i)
    check_edge(s, v[i - 1], v[i], v[i].line, fmt::format("polygon edge {}-{}", i, i + 1));
  check_edge(s, v[n - 1], v[0], end, fmt::format("closing polygon edge {}-1", n));
  s.polygons.push_back(ScenePolygon{std::move(v), line, std::move(st)});
}

void build_line(Scene& s, std::vector<ScenePoint>&& v, int line, int /*end*/, SceneStyle&& st) {
  const ScenePoint &p = v[0], &q = v[1];
  if (q.point == p.point || q.point == antipode(p.point))
    throw ParseError(s.name, q.line,
                     fmt::format("line: join(p, q) is undefined when q = p or q = antipode(p); here p = {} "
                                 "(line {}) and q = {} (line {})",
                                 to_string(p.point), p.line, to_string(q.point), q.line));
  s.lines.push_back(SceneLine{p, q, line, std::move(st)});
}

void build_circle(Scene& s, std::vector<ScenePoint>&& v, int line, int /*end*/, SceneStyle&& st) {
  const ScenePoint &c = v[0], &p = v[1];
  if (c.point.w() == 0 && p.point.w() == 0)
    throw ParseError(s.name, p.line,
                     fmt::format("circle: undefined when both the centre {} (line {}) and the point {} "
                                 "(line {}) are at infinity",
                                 to_string(c.point), c.line, to_string(p.point), p.line));
  s.circles.push_back(SceneCircle{c, p, line, std::move(st)});
}

struct BlockKind {
  std::string_view keyword;  // the word that opens the block
  std::size_t points;        // how many points it holds: exactly, or at least when at_least
  bool at_least;
  std::string_view noun;     // what its points are called in messages
  SceneKind kind;            // the kind its style attributes are checked against
  void (*build)(Scene&, std::vector<ScenePoint>&&, int line, int end, SceneStyle&& style);
};

constexpr BlockKind kBlockKinds[] = {
    {"segment", 2, false, "points", SceneKind::segment, build_segment},
    {"polygon", 3, true, "vertices", SceneKind::polygon, build_polygon},
    {"line", 2, false, "points", SceneKind::line, build_line},
    {"circle", 2, false, "points", SceneKind::circle, build_circle},
};

const BlockKind* find_block(std::string_view word) {
  for (const auto& k : kBlockKinds)
    if (word == k.keyword) return &k;
  return nullptr;
}

bool is_keyword(std::string_view w) {
  return w == "label" || w == "end" || w == "style" || find_block(w) != nullptr;
}

// The block keywords as a list: "segment, polygon, line" then `last` then "circle".
std::string block_list(std::string_view last) {
  std::string s;
  const std::size_t n = std::size(kBlockKinds);
  for (std::size_t i = 0; i < n; ++i) {
    if (i > 0) s += i + 1 == n ? last : ", ";
    s += kBlockKinds[i].keyword;
  }
  return s;
}

// An open block.
struct Block {
  const BlockKind* kind = nullptr;
  int line = 0;
  std::vector<ScenePoint> points;
  SceneStyle style;
};

class Parser {
 public:
  Parser(std::string_view text, std::string name) : text_(text) { scene_.name = std::move(name); }

  Scene run() {
    if (text_.starts_with("\xEF\xBB\xBF")) text_.remove_prefix(3);  // UTF-8 byte order mark
    std::size_t pos = 0;
    while (pos < text_.size()) {
      if (line_ == INT_MAX) fail("the file has too many lines");
      ++line_;
      std::size_t nl = text_.find('\n', pos);
      if (nl == std::string_view::npos) nl = text_.size();
      std::string_view s = text_.substr(pos, nl - pos);
      pos = nl + 1;
      const auto words = split(s);
      if (!words.empty()) handle(words);
    }
    if (block_)
      throw ParseError(scene_.name, block_->line,
                       fmt::format("'{}' block is not closed: 'end' is missing", block_->kind->keyword));
    return std::move(scene_);
  }

 private:
  [[noreturn]] void fail(const std::string& message) const {
    throw ParseError(scene_.name, line_, message);
  }
  // Splits a line into words. '#' starts a comment, except right after '=' (the colour of
  // `color=#d62728`); a value that starts with '"' right after the word's first '=' runs to the
  // next '"' and may hold spaces and '#' (`label="convex hull #2"`). No other '"' is allowed:
  // `label=="x"` would give the label `="x"`, which no quoting writes back.
  std::vector<std::string_view> split(std::string_view s) const {
    std::vector<std::string_view> words;
    std::size_t i = 0;
    while (i < s.size()) {
      while (i < s.size() && is_space(s[i])) ++i;
      const std::size_t b = i;
      while (i < s.size() && !is_space(s[i])) {
        if (s[i] == '#' && (i == b || s[i - 1] != '=')) break;
        if (s[i] == '"') {
          const std::size_t close = s.find('"', i + 1);
          if (i == b || s.find('=', b) != i - 1 || close == std::string_view::npos)
            fail(fmt::format("{}: a quoted value follows '=' and ends with '\"'", quote(s.substr(b))));
          i = close + 1;
          if (i < s.size() && !is_space(s[i])) fail(fmt::format("{}: a space must follow the closing '\"'", quote(s.substr(b))));
          break;
        }
        ++i;
      }
      if (i > b) words.push_back(s.substr(b, i - b));
      if (i < s.size() && s[i] == '#') break;
    }
    return words;
  }

  // The attributes `key=value` of a line (the words from `from` on) as a style for an object of
  // `kind` (any kind for a `style` line).
  SceneStyle attributes(const std::vector<std::string_view>& w, std::size_t from, std::optional<SceneKind> kind) const {
    SceneStyle st;
    std::vector<std::string_view> seen;
    for (std::size_t i = from; i < w.size(); ++i) {
      const std::size_t eq = w[i].find('=');
      const std::string_view key = w[i].substr(0, eq);
      std::string_view value = w[i].substr(eq + 1);
      if (value.size() >= 2 && value.front() == '"') value = value.substr(1, value.size() - 2);
      if (std::find(seen.begin(), seen.end(), key) != seen.end())
        fail(fmt::format("attribute {} is given twice on this line", quote(key)));
      seen.push_back(key);
      try {
        set_scene_attribute(st, key, value, kind);
      } catch (const BadInput& e) {
        fail(e.what());
      }
    }
    return st;
  }

  void no_more(const std::vector<std::string_view>& w) const {
    if (w.size() > 1)
      fail(fmt::format("'{}' stands alone on its line, found {} after it", w[0], quote(w[1])));
  }

  void handle(const std::vector<std::string_view>& line) {
    // The object's words, then its attributes: every word after the first attribute is one.
    std::size_t a = 0;
    while (a < line.size() && !is_attribute(line[a])) ++a;
    if (a == 0)
      fail(fmt::format("style attributes without an object: write {} after a point, on a block's keyword "
                       "line or on a 'style' line",
                       quote(line[0])));
    for (std::size_t i = a; i < line.size(); ++i)
      if (!is_attribute(line[i]))
        fail(fmt::format("{} after the style attributes: attributes come last on a line", quote(line[i])));
    const std::vector<std::string_view> w(line.begin(), line.begin() + static_cast<std::ptrdiff_t>(a));
    const std::string_view first = w[0];
    if (a < line.size() && block_ && !find_block(first) && first != "end")
      fail(fmt::format("style attributes inside the '{}' block: write them on its '{}' line (line {})",
                       block_->kind->keyword, block_->kind->keyword, block_->line));
    if (first == "style") {
      no_more(w);
      if (block_)
        fail(fmt::format("'style' inside the '{}' block opened on line {}", block_->kind->keyword, block_->line));
      defaults_ = attributes(line, a, std::nullopt);
    } else if (const BlockKind* kind = find_block(first)) {
      no_more(w);
      if (block_)
        fail(fmt::format("'{}' inside the '{}' block opened on line {} ('end' missing?)", first,
                         block_->kind->keyword, block_->line));
      block_.emplace();
      block_->kind = kind;
      block_->line = line_;
      block_->style = merged(defaults_, attributes(line, a, kind->kind), kind->kind);
    } else if (first == "end") {
      no_more(w);
      if (a < line.size()) fail("'end' takes no attributes: write them on the block's keyword line");
      if (!block_) fail(fmt::format("'end' without an open block ({})", block_list(" or ")));
      close_block();
    } else if (first == "label") {
      if (block_)
        fail(fmt::format("'label' inside the '{}' block opened on line {}: label the point before "
                         "the block, then write its name in the block",
                         block_->kind->keyword, block_->line));
      if (w.size() < 2) fail("'label' needs a name and a point: label NAME x y, or label NAME w x y");
      if (!is_name(w[1]))
        fail(fmt::format("{} is not a label name: use letters, digits, _ and ', starting with a "
                         "letter or _",
                         quote(w[1])));
      if (is_keyword(w[1])) fail(fmt::format("{} is a keyword, not a label name", quote(w[1])));
      if (is_non_finite_number(w[1])) fail(fmt::format("{} reads as a number, not a label name", quote(w[1])));
      if (const auto old = labels_.find(std::string(w[1])); old != labels_.end())
        fail(fmt::format("label {} is already defined on line {}", quote(w[1]),
                         scene_.points[old->second].line));
      if (w.size() == 2) fail(fmt::format("label {} has no point: label NAME x y, or label NAME w x y", quote(w[1])));
      ScenePoint p = point({w.begin() + 2, w.end()});
      p.label = std::string(w[1]);
      p.style = merged(defaults_, attributes(line, a, SceneKind::point), SceneKind::point);
      labels_.emplace(p.label, scene_.points.size());
      scene_.points.push_back(std::move(p));
    } else if (const auto found = block_ ? labels_.find(std::string(first)) : labels_.end();
               found != labels_.end()) {
      no_more(w);
      const ScenePoint& p = scene_.points[found->second];
      block_->points.push_back(ScenePoint{p.point, line_, p.label, {}});
    } else if (is_letter(first[0]) && !is_non_finite_number(first)) {
      if (!block_)
        fail(fmt::format("unknown keyword {} (the keywords are label, style, {}, end)", quote(first), block_list(", ")));
      fail(fmt::format("{} is neither a keyword nor a label defined above", quote(first)));
    } else {
      ScenePoint p = point(w);
      if (block_) {
        block_->points.push_back(std::move(p));
      } else {
        p.style = merged(defaults_, attributes(line, a, SceneKind::point), SceneKind::point);
        scene_.points.push_back(std::move(p));
      }
    }
  }

  double number(std::string_view t) const {
    std::string_view s = t;
    if (s.size() > 1 && s[0] == '+' && s[1] != '-' && s[1] != '+') s.remove_prefix(1);
    double v = 0;
    const auto r = std::from_chars(s.data(), s.data() + s.size(), v);
    if (r.ptr != s.data() + s.size() || r.ec == std::errc::invalid_argument)
      fail(fmt::format("{} is not a number", quote(t)));
    if (r.ec == std::errc::result_out_of_range) {
      // from_chars refuses both overflow and underflow to zero; strtod tells them apart.
      const std::string copy(s);
      const double big = std::strtod(copy.c_str(), nullptr);
      if (std::isinf(big)) fail(fmt::format("{} is too large for a double", quote(t)));
      fail(fmt::format("{} is too small for a double: it would round to 0", quote(t)));
    }
    if (!std::isfinite(v)) fail(fmt::format("{} is not a finite number", quote(t)));
    return v;
  }

  ScenePoint point(const std::vector<std::string_view>& w) const {
    for (auto t : w) (void)number(t);  // report a bad number before a bad count
    if (w.size() != 2 && w.size() != 3)
      fail(fmt::format("a point is 2 numbers (x y) or 3 (w x y), found {}", w.size()));
    double c[3] = {1, 0, 0};
    for (std::size_t i = 0; i < w.size(); ++i) c[3 - w.size() + i] = number(w[i]);
    if (c[0] == 0 && c[1] == 0 && c[2] == 0) fail("[0,0,0] is not a point of T2");
    return ScenePoint{Point(c[0], c[1], c[2]), line_, {}, {}};
  }

  void close_block() {
    Block b = std::move(*block_);
    block_.reset();
    const BlockKind& k = *b.kind;
    const std::size_t n = b.points.size();
    if (k.at_least ? n < k.points : n != k.points)
      fail(fmt::format("a {} has {} {} {}, this one has {}", k.keyword, k.at_least ? "at least" : "exactly", k.points,
                       k.noun, n));
    k.build(scene_, std::move(b.points), b.line, line_, std::move(b.style));
  }

  std::string_view text_;
  Scene scene_;
  int line_ = 0;
  std::optional<Block> block_;
  SceneStyle defaults_;  // the attributes of the last 'style' line
  std::unordered_map<std::string, std::size_t> labels_;  // name -> index in scene_.points
};

}  // namespace

std::vector<std::string_view> scene_block_keywords() {
  std::vector<std::string_view> v;
  for (const auto& k : kBlockKinds) v.push_back(k.keyword);
  return v;
}

Scene parse_scene(std::string_view text, std::string name) { return Parser(text, std::move(name)).run(); }

Scene read_scene(const std::filesystem::path& path) {
  std::string text;
  try {
    text = read_file(path);
  } catch (const std::system_error& e) {
    throw BadInput(fmt::format("{}: cannot read the scene file: {}", path.string(), e.code().message()));
  }
  return parse_scene(text, path.string());
}

}  // namespace t2
