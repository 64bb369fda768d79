// Wrong on purpose: the in-circle determinant evaluated in doubles, without a filter or exact
// fallback. On nearly cocircular points it gets signs wrong, and its inconsistent answers can
// make the flips go round in circles: the "safety limit" below then stops it, not Delaunay.
#include "lawson.hpp"

#include <array>
#include <map>
#include <utility>


namespace ex10 {

static double in_circle_double(const t2::Point& a, const t2::Point& b, const t2::Point& c, const t2::Point& d) {
  const double adx = a.x() - d.x(), ady = a.y() - d.y(), bdx = b.x() - d.x(), bdy = b.y() - d.y(),
               cdx = c.x() - d.x(), cdy = c.y() - d.y();
  return (adx * adx + ady * ady) * (bdx * cdy - cdx * bdy) - (bdx * bdx + bdy * bdy) * (adx * cdy - cdx * ady) +
         (cdx * cdx + cdy * cdy) * (adx * bdy - bdx * ady);
}

std::vector<long> delaunay_flips(const std::vector<t2::Point>& P, const std::vector<long>& T) {
  std::vector<std::array<long, 3>> tri;
  for (std::size_t k = 0; k + 2 < T.size(); k += 3) tri.push_back({T[k], T[k + 1], T[k + 2]});
  std::map<std::pair<long, long>, long> owner;  // directed edge a -> b: the triangle holding it
  auto link = [&](long t, bool on) {
    for (int i = 0; i < 3; ++i) {
      const std::pair<long, long> e{tri[t][i], tri[t][(i + 1) % 3]};
      if (on) owner[e] = t; else owner.erase(e);
    }
  };
  for (long t = 0; t < long(tri.size()); ++t) link(t, true);
  std::vector<std::pair<long, long>> stack;
  for (const auto& [e, t] : owner)
    if (e.first < e.second) stack.push_back(e);
  auto third = [&](long t, long a, long b) {
    for (long v : tri[t])
      if (v != a && v != b) return v;
    return -1L;
  };
  for (std::size_t flips = 0; !stack.empty() && flips < 100 * P.size();) {
    const auto [a, b] = stack.back();
    stack.pop_back();
    const auto ab = owner.find({a, b}), ba = owner.find({b, a});
    if (ab == owner.end() || ba == owner.end()) continue;  // a hull edge, or flipped away
    const long t = ab->second, u = ba->second, c = third(t, a, b), d = third(u, b, a);
    // t = (a, b, c) and u = (b, a, d), counter-clockwise: illegal when d is inside the circle.
    if (in_circle_double(P[a], P[b], P[c], P[d]) <= 0) continue;
    ++flips;
    link(t, false);
    link(u, false);
    tri[t] = {a, d, c};  // the quadrilateral a, d, b, c, cut by c d
    tri[u] = {d, b, c};
    link(t, true);
    link(u, true);
    for (auto [x, y] : {std::pair{a, d}, {d, b}, {b, c}, {c, a}}) stack.push_back({std::min(x, y), std::max(x, y)});
  }
  std::vector<long> out;
  for (const auto& t : tri) out.insert(out.end(), t.begin(), t.end());
  return out;
}

}  // namespace ex10
