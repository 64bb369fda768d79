#pragma once
// Exercise 10: the exact certificate both test files check an answer with (part of the tests,
// not of your solution). An answer is right when it is a triangulation of the same points with
// the same hull as the input (every triangle counter-clockwise, every directed edge used once,
// the boundary edges those of the input, the areas summing to the input's exactly) and every
// interior edge is locally Delaunay under the exact t2::in_circle.
#include <map>
#include <string>
#include <utility>
#include <vector>

#include <t2/kernel/incircle.hpp>
#include <t2/kernel/number.hpp>
#include <t2/kernel/orient.hpp>
#include <t2/kernel/point.hpp>

namespace ex10test {

/// Twice the area of a b c, exactly (front points).
inline t2::Rational area2(const t2::Point& a, const t2::Point& b, const t2::Point& c) {
  auto q = [](double v) { return t2::to_rational(v); };
  const t2::Rational ax = q(a.x()) / q(a.w()), ay = q(a.y()) / q(a.w()), bx = q(b.x()) / q(b.w()),
                     by = q(b.y()) / q(b.w()), cx = q(c.x()) / q(c.w()), cy = q(c.y()) / q(c.w());
  return (bx - ax) * (cy - ay) - (by - ay) * (cx - ax);
}

/// "" when `out` is a Delaunay triangulation of P with the hull of `in`, else what is wrong.
inline std::string check(const std::vector<t2::Point>& P, const std::vector<long>& in, const std::vector<long>& out) {
  if (out.size() != in.size()) return "the answer has " + std::to_string(out.size() / 3) + " triangles, the input " +
                                      std::to_string(in.size() / 3) + ": a flip keeps the number of triangles";
  auto edges = [&](const std::vector<long>& T, std::map<std::pair<long, long>, long>& e) -> std::string {
    for (std::size_t k = 0; k < T.size(); k += 3) {
      for (int i = 0; i < 3; ++i) {
        if (T[k + i] < 0 || T[k + i] >= long(P.size())) return "a vertex index out of range";
        if (!e.emplace(std::pair{T[k + i], T[k + (i + 1) % 3]}, long(k / 3)).second)
          return "the directed edge " + std::to_string(T[k + i]) + " -> " + std::to_string(T[k + (i + 1) % 3]) +
                 " is in two triangles";
      }
      if (t2::orient(P[T[k]], P[T[k + 1]], P[T[k + 2]]) != t2::POSITIVE)
        return "triangle " + std::to_string(T[k]) + " " + std::to_string(T[k + 1]) + " " + std::to_string(T[k + 2]) +
               " is not counter-clockwise";
    }
    return "";
  };
  std::map<std::pair<long, long>, long> ein, eout;
  if (const std::string w = edges(in, ein); !w.empty()) return "bad test input: " + w;
  if (const std::string w = edges(out, eout); !w.empty()) return w;
  for (const auto& [e, t] : ein)
    if (!ein.count({e.second, e.first}) && !eout.count(e))
      return "the hull edge " + std::to_string(e.first) + " -> " + std::to_string(e.second) + " is missing";
  t2::Rational a = 0, b = 0;
  for (std::size_t k = 0; k < in.size(); k += 3) a += area2(P[in[k]], P[in[k + 1]], P[in[k + 2]]);
  for (std::size_t k = 0; k < out.size(); k += 3) b += area2(P[out[k]], P[out[k + 1]], P[out[k + 2]]);
  if (a != b) return "the triangles do not cover the hull exactly once";
  for (const auto& [e, t] : eout) {
    const auto other = eout.find({e.second, e.first});
    if (other == eout.end()) {
      if (!ein.count(e) || ein.count({e.second, e.first})) return "an edge with one triangle inside the hull";
      continue;
    }
    long c = -1, d = -1;
    for (int i = 0; i < 3; ++i) {
      const long v = out[3 * t + i], w = out[3 * other->second + i];
      if (v != e.first && v != e.second) c = v;
      if (w != e.first && w != e.second) d = w;
    }
    if (t2::in_circle(P[e.first], P[e.second], P[c], P[d]) == t2::POSITIVE)
      return "the edge " + std::to_string(e.first) + " " + std::to_string(e.second) + " is illegal: point " +
             std::to_string(d) + " is inside the circle of " + std::to_string(e.first) + " " + std::to_string(e.second) +
             " " + std::to_string(c);
  }
  return "";
}

}  // namespace ex10test
