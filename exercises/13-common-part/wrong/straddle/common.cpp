// Wrong on purpose: the plane's test for two crossing segments, "c and d on opposite sides of
// ab, a and b on opposite sides of cd", with either sign of n x m. In T² the two segments may
// reach the other's line at antipodal points (s and the antipode of t), and then do not meet.
#include "common.hpp"

namespace ex13 {

namespace {

using t2::ExactPoint;
using t2::Integer;

struct V {
  Integer w, x, y;
};

V vec(const ExactPoint& p) { return {p.w(), p.x(), p.y()}; }
V cross(const V& a, const V& b) {
  return {a.x * b.y - a.y * b.x, a.y * b.w - a.w * b.y, a.w * b.x - a.x * b.w};
}
Integer dot(const V& a, const V& b) { return a.w * b.w + a.x * b.x + a.y * b.y; }
bool zero(const V& a) { return a.w == 0 && a.x == 0 && a.y == 0; }

// p on the segment ab (a ≠ ¬b): with n = a × b ≠ 0 and p = αa + βb in the plane of a and b,
// a × p = β n and p × b = α n, so α, β ≥ 0 is two signs of dot products.
bool on(const V& p, const V& a, const V& b) {
  const V n = cross(a, b);
  if (zero(n)) return zero(cross(a, p)) && dot(a, p) > 0;  // a = b: the one point a
  if (dot(p, n) != 0) return false;                          // off the line of ab
  return dot(cross(a, p), n) >= 0 && dot(cross(p, b), n) >= 0;
}

ExactPoint point(const V& v) { return ExactPoint(v.w, v.x, v.y); }

}  // namespace

std::vector<ExactPoint> common(const t2::Point& pa, const t2::Point& pb, const t2::Point& pc, const t2::Point& pd) {
  const V a = vec(t2::to_exact(pa)), b = vec(t2::to_exact(pb)), c = vec(t2::to_exact(pc)), d = vec(t2::to_exact(pd));
  const V n = cross(a, b), m = cross(c, d);
  if (!zero(n) && !zero(m) && !zero(cross(n, m))) {  // two different lines: ±(n × m)
    const V l = cross(n, m), k = {-l.w, -l.x, -l.y};
    const bool on_s = on(l, a, b) || on(k, a, b), on_t = on(l, c, d) || on(k, c, d);
    if (!on_s || !on_t) return {};
    return {point(on(l, a, b) ? l : k)};
  }
  // One segment is a point, or both lie on one line: the ends of the common part are endpoints.
  std::vector<V> ends;
  auto add = [&](const V& p) {
    for (const auto& e : ends)
      if (zero(cross(e, p)) && dot(e, p) > 0) return;
    ends.push_back(p);
  };
  if (on(a, c, d)) add(a);
  if (on(b, c, d)) add(b);
  if (on(c, a, b)) add(c);
  if (on(d, a, b)) add(d);
  std::vector<ExactPoint> r;
  for (const auto& e : ends) r.push_back(point(e));
  return r;
}

}  // namespace ex13
