// Wrong on purpose, by its time only: the right faces, but the owner of each hull edge is
// searched among all the sites of the other side, O(h n) after the hulls. On 10⁵ sites in convex
// position (h = n) that is 5·10⁹ exact comparisons; the merge of chapter 10, section 8 needs O(h).
#include "band.hpp"

#include <algorithm>
#include <array>
#include <string>

#include <t2/kernel/angle.hpp>
#include <t2/kernel/error.hpp>
#include <t2/kernel/lexicographic.hpp>
#include <t2/kernel/orient.hpp>

namespace ex10c {

namespace {

using t2::Point;

// The drawn position of a site, as a front point (the antipode of a back site).
Point drawn(const Point& p) { return p.w() > 0 ? p : t2::antipode(p); }

// The hull cycle of the sites s at their drawn positions D, counter-clockwise, through every
// site on the boundary: the lower chain, then the upper one, each popping only at a strict right
// turn. Collinear sites give s0 … sk … s1, the segment both ways; one site gives itself.
std::vector<long> hull_cycle(const std::vector<Point>& D, std::vector<long> s) {
  std::sort(s.begin(), s.end(), [&](long a, long b) { return t2::compare_xy(D[a], D[b]) == t2::NEGATIVE; });
  if (s.size() < 2) return s;
  std::vector<long> h;
  for (int chain = 0; chain < 2; ++chain) {
    const std::size_t base = h.size();
    for (long p : s) {
      while (h.size() >= base + 2 && t2::orient(D[h[h.size() - 2]], D[h.back()], D[p]) == t2::NEGATIVE) h.pop_back();
      h.push_back(p);
    }
    h.pop_back();  // the last site of a chain starts the next one
    std::reverse(s.begin(), s.end());
  }
  return h;
}

// Is x a better owner than y for the hull edge p -> q: farther to the left of it, or as far and
// farther along it (forward) or against it (chapter 10, section 8's tie rule)?
bool better(const std::vector<Point>& D, long p, long q, long x, long y, bool forward) {
  const t2::Sign c = t2::detail::cross_of_differences(D[p], D[q], D[y], D[x]);
  if (c != t2::ZERO) return c == t2::POSITIVE;
  return t2::detail::dot_of_differences(D[p], D[q], D[y], D[x]) == (forward ? t2::POSITIVE : t2::NEGATIVE);
}

}  // namespace

std::vector<long> owners(const std::vector<Point>& P, const Point& z) {
  // For front points p, q and r = [0, -uy, ux]: orient(p, q, r) = sign(u · (Q - P)).
  const Point ahead(0, -z.y(), z.x()), behind(0, z.y(), -z.x());
  long best[2] = {-1, -1};
  bool tie[2] = {false, false};
  for (long k = 0; k < long(P.size()); ++k) {
    const int side = P[k].w() > 0 ? 0 : 1;
    const Point& r = side == 0 ? ahead : behind;
    if (best[side] < 0) {
      best[side] = k;
      continue;
    }
    const t2::Sign s = t2::orient(drawn(P[best[side]]), drawn(P[k]), r);
    if (s == t2::POSITIVE) best[side] = k, tie[side] = false;
    else if (s == t2::ZERO) tie[side] = true;
  }
  if (tie[0] || tie[1])
    throw t2::Undefined("owners: two " + std::string(tie[0] ? "front" : "back") +
                        " sites are extreme: the point is a break on Omega");
  return {best[0], best[1]};
}

std::vector<long> band(const std::vector<Point>& P) {
  std::vector<Point> D;
  std::vector<long> front, back;
  for (long k = 0; k < long(P.size()); ++k) {
    D.push_back(drawn(P[k]));
    (P[k].w() > 0 ? front : back).push_back(k);
  }
  const std::vector<long> cf = hull_cycle(D, front), cb = hull_cycle(D, back);
  std::vector<long> out;
  for (int s = 0; s < 2; ++s) {  // each hull edge, its owner searched among all sites of the other side
    const std::vector<long>& c = s == 0 ? cf : cb;
    const std::vector<long>& other = s == 0 ? back : front;
    for (std::size_t i = 0; c.size() >= 2 && i < c.size(); ++i) {
      const long u = c[i], v = c[(i + 1) % c.size()];
      long o = other[0];
      for (long x : other)
        if (better(D, u, v, x, o, s == 0)) o = x;
      out.insert(out.end(), {s == 0 ? v : u, s == 0 ? u : v, o});
    }
  }
  for (std::size_t k = 0; k < out.size(); k += 3) {
    const Point &x = P[out[k]], &y = P[out[k + 1]], &o = P[out[k + 2]];
    if (t2::orient(x, y, o) == t2::ZERO && !(o == t2::antipode(x) || o == t2::antipode(y)))
      throw t2::Undefined("band: the site " + std::to_string(out[k + 2]) + " is drawn on the line of the hull edge " +
                          std::to_string(out[k]) + ", " + std::to_string(out[k + 1]) + ": a flat face");
  }
  return out;
}

}  // namespace ex10c
