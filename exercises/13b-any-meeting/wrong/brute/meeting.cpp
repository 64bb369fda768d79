// Wrong on purpose: right answers by brute force, every pair of segments tested exactly (the
// common-part test of exercise 13, O(n²) pairs). Too slow for the large inputs.
#include "meeting.hpp"

#include <t2/kernel/number.hpp>

namespace ex13b {

namespace {

using t2::Integer;

struct V {
  Integer w, x, y;
};

V vec(const t2::Point& p) {
  const t2::ExactPoint e = t2::to_exact(p);
  return {e.w(), e.x(), e.y()};
}
V cross(const V& a, const V& b) { return {a.x * b.y - a.y * b.x, a.y * b.w - a.w * b.y, a.w * b.x - a.x * b.w}; }
Integer dot(const V& a, const V& b) { return a.w * b.w + a.x * b.x + a.y * b.y; }
bool zero(const V& a) { return a.w == 0 && a.x == 0 && a.y == 0; }

// p on the segment ab (a ≠ ¬b): p = αa + βb with a × p = β n, p × b = α n (n = a × b).
bool on(const V& p, const V& a, const V& b) {
  const V n = cross(a, b);
  if (zero(n)) return zero(cross(a, p)) && dot(a, p) > 0;
  if (dot(p, n) != 0) return false;
  return dot(cross(a, p), n) >= 0 && dot(cross(p, b), n) >= 0;
}

bool meet(const V& a, const V& b, const V& c, const V& d) {
  const V n = cross(a, b), m = cross(c, d);
  if (!zero(n) && !zero(m) && !zero(cross(n, m))) {  // two lines: the common points ±(n × m)
    V l = cross(n, m);
    if (on(l, a, b) && on(l, c, d)) return true;
    l = {-l.w, -l.x, -l.y};
    return on(l, a, b) && on(l, c, d);
  }
  return on(a, c, d) || on(b, c, d) || on(c, a, b) || on(d, a, b);
}

}  // namespace

std::vector<long> meeting_pair(const std::vector<t2::Point>& a, const std::vector<t2::Point>& b) {
  std::vector<V> ea, eb;
  for (std::size_t i = 0; i < a.size(); ++i) ea.push_back(vec(a[i])), eb.push_back(vec(b[i]));
  for (std::size_t i = 0; i < a.size(); ++i)
    for (std::size_t j = i + 1; j < a.size(); ++j)
      if (meet(ea[i], eb[i], ea[j], eb[j])) return {long(i), long(j)};
  return {};
}

}  // namespace ex13b
