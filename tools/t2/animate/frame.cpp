// The picture of one step of `t2 animate` (frame.hpp).
#include "animate/frame.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "t2/kernel/circle.hpp"
#include "t2/draw.hpp"
#include "t2/kernel/error.hpp"

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

// A segment of T², unless it is undefined (equal or antipodal ends): then nothing.
void segment(dr::Figure& f, const Point& a, const Point& b, const dr::Style& s) {
  if (a == b || a == t2::antipode(b)) return;
  f.segment(a, b, s);
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

}  // namespace

std::string frame_svg(const std::vector<Point>& P, const t2::trace::Step& s) {
  dr::Figure f;
  for (const auto& t : s.triangles)  // the triangulation so far
    for (int k = 0; k < 3; ++k) segment(f, P[t[k]], P[t[(k + 1) % 3]], dr::Style().color(kMesh).width(1).layer(0));
  for (const auto& t : s.touched) {  // the triangles in focus
    if (P[t[0]] == P[t[1]] || P[t[1]] == P[t[2]] || P[t[2]] == P[t[0]]) continue;
    // a lune of T² (two antipodal vertices): no segment between them to fill; its edges show
    if (P[t[0]] == t2::antipode(P[t[1]]) || P[t[1]] == t2::antipode(P[t[2]]) || P[t[2]] == t2::antipode(P[t[0]]))
      continue;
    f.add(std::vector<Point>{P[t[0]], P[t[1]], P[t[2]]},
          dr::Style().color(kTouched).width(1.6).fill(kTouched).fill_opacity(0.3).layer(1));
  }
  if (s.circle.size() == 3) {  // the circle of an in-circle test
    try {
      f.add(t2::circle_through(P[s.circle[0]], P[s.circle[1]], P[s.circle[2]]),
            dr::Style().color(kCircle).width(1.4).dash({5, 3}).layer(1));
    } catch (const t2::Undefined&) {  // collinear or at infinity: no circle to draw
    }
  }
  std::vector<Point> chain;
  for (std::size_t i : s.chain) chain.push_back(P[i]);
  const dr::Style ch = dr::Style().color(s.closed ? kHull : kChain).width(2.4).layer(2);
  if (s.closed && chain.size() >= 3) {
    f.add(chain, dr::Style(ch).fill(kHull).fill_opacity(0.18));
  } else {
    for (std::size_t k = 1; k < chain.size(); ++k) segment(f, chain[k - 1], chain[k], ch);
    if (s.closed && chain.size() == 2) segment(f, chain[0], chain[1], ch);
  }
  for (const auto& e : s.edges)  // candidate edges, bridges, new edges
    segment(f, P[e[0]], P[e[1]], dr::Style().color(kFocus).width(2).dash({6, 3}).layer(3));
  const bool labels = P.size() <= 40;
  for (std::size_t i = 0; i < P.size(); ++i) {
    const bool on_chain = std::find(s.chain.begin(), s.chain.end(), i) != s.chain.end();
    dr::Style st = dr::Style().color(on_chain ? "#000000" : kGrey).layer(4);
    if (labels) st.label(fmt::format("p{}", i)).label_angle(45);
    f.add(P[i], st);
  }
  for (std::size_t k = 0; k < s.points.size(); ++k)  // the current point first, larger
    f.add(P[s.points[k]], dr::Style().color(kFocus).size(k == 0 ? 6 : 4.5).layer(5));
  std::string svg = dr::render_both(f, plane_view(P), dr::SphereView());
  if (svg.rfind("<?xml", 0) == 0) svg.erase(0, svg.find("?>") + 2);
  return svg;
}

}  // namespace t2cli::animate
