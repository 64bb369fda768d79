// The picture of one step of `t2 animate` (frame.hpp).
#include "animate/frame.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <numbers>

#include "t2/draw.hpp"
#include "t2/draw/scene_figure.hpp"

namespace t2cli::animate {
namespace {

namespace dr = t2::draw;
using t2::Point;

const char* const kGrey = "#9a9a9a";
const char* const kMesh = "#6f8fb0";
const char* const kChain = "#1f77b4";
const char* const kHull = "#2ca02c";
const char* const kFocus = "#d62728";
const char* const kTouched = "#ff7f0e";
const char* const kCircle = "#9467bd";
const char* const kCurve = "#17becf";
constexpr int kSize = 360;  // each model's picture, in SVG units (the page scales it to its width)

// A segment of T², unless it is undefined (equal or antipodal ends): then nothing.
void segment(dr::Figure& f, const Point& a, const Point& b, const dr::Style& s) {
  if (a == b || a == t2::antipode(b)) return;
  f.segment(a, b, s);
}

// The points a step's text names ("p12"; segments "s12" with prefix 's'), which alone get
// labels: with every point labelled, the labels of a few dozen points pile up into an
// unreadable heap.
std::vector<bool> named(const std::string& text, std::size_t n, char prefix = 'p') {
  std::vector<bool> out(n, false);
  for (std::size_t k = 0; k + 1 < text.size(); ++k) {
    if (text[k] != prefix || (k > 0 && std::isalnum(static_cast<unsigned char>(text[k - 1]))) ||
        !std::isdigit(static_cast<unsigned char>(text[k + 1])))
      continue;
    std::size_t i = 0, j = k + 1;
    for (; j < text.size() && std::isdigit(static_cast<unsigned char>(text[j])) && i <= n; ++j)
      i = 10 * i + static_cast<std::size_t>(text[j] - '0');
    if (i < n && (j == text.size() || !std::isalnum(static_cast<unsigned char>(text[j])))) out[i] = true;
  }
  return out;
}

// The spherical view looking straight at the data (the default view when they balance out).
dr::SphereView sphere_view(const std::vector<Point>& P, int size) {
  dr::SphereView v;
  v.size = size;
  return dr::facing(P, v);
}

dr::PlaneView plane_view(const std::vector<Point>& P) {
  double r = 0;
  for (const auto& p : P)
    if (p.w() != 0 && std::isfinite(std::hypot(p.x() / p.w(), p.y() / p.w())))
      r = std::max(r, std::hypot(p.x() / p.w(), p.y() / p.w()));
  dr::PlaneView v;
  v.half_width = std::max(1.0, 1.15 * r);
  return v;
}

// The middle of the segment of T² from a to b, for its label (a picture: doubles).
Point middle(const Point& a, const Point& b) {
  const double na = std::hypot(a.w(), a.x(), a.y()), nb = std::hypot(b.w(), b.x(), b.y());
  return Point(a.w() / na + b.w() / nb, a.x() / na + b.x() / nb, a.y() / na + b.y() / nb);
}

// An animation of segments (frame.hpp): every segment thin, the chain's (the status) thick, and
// those the text names labelled at their middle.
void draw_segments(dr::Figure& f, const std::vector<Point>& P, const t2::trace::Step& s,
                   const std::vector<t2::trace::Edge>& segments) {
  for (const auto& e : segments) segment(f, P[e[0]], P[e[1]], dr::Style().color(kGrey).width(1.2).layer(0));
  for (std::size_t i : s.chain)
    segment(f, P[segments[i][0]], P[segments[i][1]], dr::Style().color(kChain).width(2.4).layer(2));
  const std::vector<bool> label = named(s.text, segments.size(), 's');
  for (std::size_t i = 0; i < segments.size(); ++i)
    if (label[i] && P[segments[i][0]] != P[segments[i][1]])
      f.label(middle(P[segments[i][0]], P[segments[i][1]]), fmt::format("s{}", i),
              dr::Style().label_angle(45).halo(false).layer(4));  // one place, no glyph outlines: a
                                                                   // few bytes of the page a label
}

}  // namespace

std::string frame_svg(const std::vector<Point>& P, const t2::trace::Step& s,
                      const std::vector<t2::trace::Edge>& segments) {
  dr::Figure f;
  // The triangulation so far: each edge once, from its lower index (an edge of two triangles,
  // drawn from both, was two lines of the page that differ only in direction).
  std::vector<std::pair<std::size_t, std::size_t>> mesh;
  for (const auto& t : s.triangles)
    for (int k = 0; k < 3; ++k) mesh.emplace_back(std::minmax<std::size_t>(t[k], t[(k + 1) % 3]));
  std::sort(mesh.begin(), mesh.end());
  mesh.erase(std::unique(mesh.begin(), mesh.end()), mesh.end());
  for (const auto& [i, j] : mesh) segment(f, P[i], P[j], dr::Style().color(kMesh).width(1).layer(0));
  for (const auto& t : s.touched) {  // the triangles in focus
    if (P[t[0]] == P[t[1]] || P[t[1]] == P[t[2]] || P[t[2]] == P[t[0]]) continue;
    // a lune of T² (two antipodal vertices): no segment between them to fill; its edges show
    if (P[t[0]] == t2::antipode(P[t[1]]) || P[t[1]] == t2::antipode(P[t[2]]) || P[t[2]] == t2::antipode(P[t[0]]))
      continue;
    f.add(std::vector<Point>{P[t[0]], P[t[1]], P[t[2]]},
          dr::Style().color(kTouched).width(1.6).fill(kTouched).fill_opacity(0.3).layer(1));
  }
  // What the algorithm constructed (a circle, a sweep line, ...): over the triangles.
  dr::SceneStyles over = dr::SceneStyles::in(kCircle);
  over.circle = dr::Style().color(kCircle).width(1.6).dash({5, 3}).layer(1);
  over.point = dr::Style().color(kCircle).size(3.5).layer(5);
  dr::add_scene(f, s.overlay, over);
  for (const auto& c : s.curves)  // sampled curves (a beach line): drawing only
    if (c.size() >= 2) f.polyline(c, dr::Style().color(kCurve).width(1.8).layer(1));
  if (!segments.empty()) draw_segments(f, P, s, segments);
  std::vector<Point> chain;
  for (std::size_t i : s.chain)
    if (segments.empty()) chain.push_back(P[i]);
  const dr::Style ch = dr::Style().color(s.closed ? kHull : kChain).width(2.4).layer(2);
  if (s.closed && chain.size() >= 3) {
    f.add(chain, dr::Style(ch).fill(kHull).fill_opacity(0.18));
  } else {
    for (std::size_t k = 1; k < chain.size(); ++k) segment(f, chain[k - 1], chain[k], ch);
    if (s.closed && chain.size() == 2) segment(f, chain[0], chain[1], ch);
  }
  for (const auto& e : s.edges)  // candidate edges, bridges, new edges
    segment(f, P[e[0]], P[e[1]], dr::Style().color(kFocus).width(2).dash({6, 3}).layer(3));
  const std::vector<bool> label = named(s.text, P.size());
  for (std::size_t i = 0; i < P.size(); ++i) {
    const bool on_chain = segments.empty() && std::find(s.chain.begin(), s.chain.end(), i) != s.chain.end();
    dr::Style st = dr::Style().color(on_chain ? "#000000" : kGrey).layer(4);
    if (label[i]) st.label(fmt::format("p{}", i)).label_angle(45).halo(false);  // no glyph outlines
    f.add(P[i], st);
  }
  for (std::size_t k = 0; k < s.points.size(); ++k)  // the current point first, larger
    f.add(P[s.points[k]], dr::Style().color(kFocus).size(k == 0 ? 6 : 4.5).layer(5));
  std::string svg = dr::render_both(f, plane_view(P), sphere_view(P, kSize));
  if (svg.rfind("<?xml", 0) == 0) svg.erase(0, svg.find("?>") + 2);
  return svg;
}

}  // namespace t2cli::animate
