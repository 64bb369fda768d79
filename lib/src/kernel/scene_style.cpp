// The style attributes of scene objects (see t2/kernel/scene_style.hpp).
#include "t2/kernel/scene_style.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <system_error>

#include "t2/kernel/scene_colors.hpp"
#include "t2/kernel/error.hpp"
#include "t2/kernel/number.hpp"

namespace t2 {

std::string_view name(SceneKind k) {
  switch (k) {
    case SceneKind::point: return "point";
    case SceneKind::segment: return "segment";
    case SceneKind::polygon: return "polygon";
    case SceneKind::line: return "line";
    case SceneKind::circle: return "circle";
  }
  return "?";
}

namespace {

namespace colors = t2::scene_colors;

[[noreturn]] void bad(const std::string& message) { throw BadInput(message); }

// A value for a message: quoted, at most 32 bytes, unprintable bytes as \xNN.
std::string shown(std::string_view v) {
  std::string s = "'";
  const std::size_t n = std::min<std::size_t>(v.size(), 32);
  for (std::size_t i = 0; i < n; ++i) {
    const auto c = static_cast<unsigned char>(v[i]);
    s += c < 0x20 || c >= 0x7f || c == '\\' ? fmt::format("\\x{:02x}", c) : std::string(1, static_cast<char>(c));
  }
  return s + (v.size() > n ? "...'" : "'");
}

// A finite number in [lo, hi] (lo excluded when open), whole: "2", "0.5", "-30".
double number_in(std::string_view key, std::string_view v, double lo, double hi, bool open = false) {
  double d = 0;
  const auto r = std::from_chars(v.data(), v.data() + v.size(), d);
  if (v.empty() || r.ec != std::errc() || r.ptr != v.data() + v.size() || !std::isfinite(d))
    bad(fmt::format("{}={}: {} is not a number", key, shown(v), shown(v)));
  if (d < lo || d > hi || (open && d == lo))
    bad(fmt::format("{}={}: {} must be in {}{}, {}]", key, shown(v), key, open ? "(" : "[", lo, hi));
  return d;
}

bool hex_digit(char c) { return (c >= '0' && c <= '9') || (c >= 'a' && c <= 'f') || (c >= 'A' && c <= 'F'); }

std::string colour_names() {
  std::string s;
  for (const auto& n : colors::names) s += fmt::format("{}{}", s.empty() ? "" : ", ", n.name);
  return s;
}

// "#rrggbb" (lower-cased) or a scene colour name.
std::string colour(std::string_view key, std::string_view v) {
  if (v.size() == 7 && v[0] == '#' && std::all_of(v.begin() + 1, v.end(), hex_digit)) {
    std::string s(v);
    for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return s;
  }
  if (const char* rgb = colors::named(v)) return rgb;
  bad(fmt::format("{}={}: not a colour; write #rrggbb or one of {}", key, shown(v), colour_names()));
}

bool yes_no(std::string_view key, std::string_view v) {
  if (v == "yes") return true;
  if (v == "no") return false;
  bad(fmt::format("{}={}: write {}=yes or {}=no", key, shown(v), key, key));
}

// Well-formed UTF-8 without control characters or '"' (a label is written back quoted), at most
// 200 bytes.
std::string label_text(std::string_view v) {
  if (v.size() > 200) bad(fmt::format("label={}: a label has at most 200 bytes, this one {}", shown(v), v.size()));
  for (std::size_t i = 0; i < v.size();) {
    const auto c = static_cast<unsigned char>(v[i]);
    const std::size_t n = c < 0x80 ? 1 : (c >> 5) == 0x6 ? 2 : (c >> 4) == 0xe ? 3 : (c >> 3) == 0x1e ? 4 : 0;
    bool ok = n > 0 && i + n <= v.size() && (c >= 0x20 && c != 0x7f);
    for (std::size_t k = 1; ok && k < n; ++k) ok = (static_cast<unsigned char>(v[i + k]) >> 6) == 0x2;
    if (!ok) bad(fmt::format("label={}: byte {} is a control character or not UTF-8", shown(v), i + 1));
    if (c == '"') bad(fmt::format("label={}: byte {} is '\"': a label cannot hold one", shown(v), i + 1));
    i += n;
  }
  return std::string(v);
}

std::vector<double> dash_pattern(std::string_view v) {
  if (v == "solid") return {};
  if (v == "dashed") return {6, 4};
  if (v == "dotted") return {1.5, 3};
  std::vector<double> d;
  std::size_t b = 0;
  while (true) {
    const std::size_t comma = v.find(',', b);
    d.push_back(number_in("dash", v.substr(b, comma == std::string_view::npos ? v.npos : comma - b), 0, 100, true));
    if (d.size() > 8) bad(fmt::format("dash={}: at most 8 lengths", shown(v)));
    if (comma == std::string_view::npos) return d;
    b = comma + 1;
  }
}

constexpr unsigned bit(SceneKind k) { return 1u << static_cast<unsigned>(k); }
constexpr unsigned kAll = 0x1f;
constexpr unsigned kStrokes = bit(SceneKind::segment) | bit(SceneKind::polygon) | bit(SceneKind::line) |
                              bit(SceneKind::circle);
constexpr unsigned kAreas = bit(SceneKind::polygon) | bit(SceneKind::line) | bit(SceneKind::circle);

// One row per attribute: its key, the kinds it applies to, and how its value is read.
struct Attribute {
  std::string_view key;
  unsigned kinds;
  void (*set)(SceneStyle&, std::string_view);
};

constexpr Attribute kAttributes[] = {
    {"color", kAll, [](SceneStyle& s, std::string_view v) { s.color = colour("color", v); }},
    {"width", kStrokes, [](SceneStyle& s, std::string_view v) { s.width = number_in("width", v, 0, 50, true); }},
    {"dash", kStrokes, [](SceneStyle& s, std::string_view v) { s.dash = dash_pattern(v); }},
    {"fill", kAreas,
     [](SceneStyle& s, std::string_view v) { s.fill = v == "none" ? std::string() : colour("fill", v); }},
    {"opacity", kAreas, [](SceneStyle& s, std::string_view v) { s.opacity = number_in("opacity", v, 0, 1); }},
    {"marker", bit(SceneKind::point),
     [](SceneStyle& s, std::string_view v) {
       for (std::string_view m : {"dot", "square", "diamond", "cross", "none"})
         if (v == m) return void(s.marker = std::string(m));
       bad(fmt::format("marker={}: write dot, square, diamond, cross or none", shown(v)));
     }},
    {"size", bit(SceneKind::point),
     [](SceneStyle& s, std::string_view v) { s.size = number_in("size", v, 0, 50, true); }},
    {"label", kAll, [](SceneStyle& s, std::string_view v) { s.label = label_text(v); }},
    {"label_angle", kAll,
     [](SceneStyle& s, std::string_view v) { s.label_angle = number_in("label_angle", v, -360, 360); }},
    {"layer", kAll,
     [](SceneStyle& s, std::string_view v) {
       int l = 0;
       const auto r = std::from_chars(v.data(), v.data() + v.size(), l);
       if (v.empty() || r.ec != std::errc() || r.ptr != v.data() + v.size() || l < -100 || l > 100)
         bad(fmt::format("layer={}: a layer is an integer in [-100, 100]", shown(v)));
       s.layer = l;
     }},
    {"arrow", bit(SceneKind::segment) | bit(SceneKind::line) | bit(SceneKind::circle),
     [](SceneStyle& s, std::string_view v) { s.arrow = yes_no("arrow", v); }},
    {"shade", bit(SceneKind::line), [](SceneStyle& s, std::string_view v) { s.shade = yes_no("shade", v); }},
    {"handles", kStrokes, [](SceneStyle& s, std::string_view v) { s.handles = yes_no("handles", v); }},
};

const Attribute* find(std::string_view key) {
  for (const auto& a : kAttributes)
    if (a.key == key) return &a;
  return nullptr;
}

std::string kinds_of(unsigned kinds) {
  std::string s;
  for (auto k : {SceneKind::point, SceneKind::segment, SceneKind::polygon, SceneKind::line, SceneKind::circle})
    if (kinds & bit(k)) s += fmt::format("{}{}", s.empty() ? "" : ", ", name(k));
  return s;
}

template <class T>
void over(std::optional<T>& to, const std::optional<T>& from) {
  if (from) to = from;
}

std::string number_text(double v) { return to_string(v); }

// A colour by its scene name when it has one ("green", not "#2ca02c").
std::string colour_text(const std::string& rgb) {
  for (const auto& n : colors::names)
    if (rgb == n.rgb) return n.name;
  return rgb;
}

}  // namespace

std::vector<std::string_view> scene_style_keys() {
  std::vector<std::string_view> v;
  for (const auto& a : kAttributes) v.push_back(a.key);
  return v;
}

bool scene_style_applies(std::string_view key, SceneKind k) {
  const Attribute* a = find(key);
  return a != nullptr && (a->kinds & bit(k)) != 0;
}

void set_scene_attribute(SceneStyle& s, std::string_view key, std::string_view value, std::optional<SceneKind> kind) {
  const Attribute* a = find(key);
  if (a == nullptr) {
    std::string keys;
    for (auto k : scene_style_keys()) keys += fmt::format("{}{}", keys.empty() ? "" : ", ", k);
    bad(fmt::format("unknown style attribute {} (the attributes are {})", shown(key), keys));
  }
  if (kind && (a->kinds & bit(*kind)) == 0)
    bad(fmt::format("'{}' does not apply to a {} (it applies to: {})", key, name(*kind), kinds_of(a->kinds)));
  a->set(s, value);
}

SceneStyle merged(const SceneStyle& defaults, const SceneStyle& own, SceneKind k) {
  SceneStyle d = defaults;
  const auto keep = [k](std::string_view key, auto& field) {
    if (!scene_style_applies(key, k)) field.reset();
  };
  keep("color", d.color), keep("width", d.width), keep("dash", d.dash), keep("fill", d.fill);
  keep("opacity", d.opacity), keep("marker", d.marker), keep("size", d.size), keep("label", d.label);
  keep("label_angle", d.label_angle), keep("layer", d.layer), keep("arrow", d.arrow), keep("shade", d.shade);
  keep("handles", d.handles);
  over(d.color, own.color), over(d.width, own.width), over(d.dash, own.dash), over(d.fill, own.fill);
  over(d.opacity, own.opacity), over(d.marker, own.marker), over(d.size, own.size), over(d.label, own.label);
  over(d.label_angle, own.label_angle), over(d.layer, own.layer), over(d.arrow, own.arrow);
  over(d.shade, own.shade), over(d.handles, own.handles);
  return d;
}

std::string to_attributes(const SceneStyle& s) {
  std::string t;
  const auto yes = [](bool b) { return b ? "yes" : "no"; };
  if (s.color) t += " color=" + colour_text(*s.color);
  if (s.width) t += " width=" + number_text(*s.width);
  if (s.dash) {
    std::string d;
    for (double x : *s.dash) d += (d.empty() ? "" : ",") + number_text(x);
    t += " dash=" + (d.empty() ? std::string("solid") : d);
  }
  if (s.fill) t += " fill=" + (s.fill->empty() ? std::string("none") : colour_text(*s.fill));
  if (s.opacity) t += " opacity=" + number_text(*s.opacity);
  if (s.marker) t += " marker=" + *s.marker;
  if (s.size) t += " size=" + number_text(*s.size);
  if (s.label) t += " label=\"" + *s.label + "\"";
  if (s.label_angle) t += " label_angle=" + number_text(*s.label_angle);
  if (s.layer) t += fmt::format(" layer={}", *s.layer);
  if (s.arrow) t += fmt::format(" arrow={}", yes(*s.arrow));
  if (s.shade) t += fmt::format(" shade={}", yes(*s.shade));
  if (s.handles) t += fmt::format(" handles={}", yes(*s.handles));
  return t;
}

}  // namespace t2
