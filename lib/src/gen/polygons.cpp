// The polygon and segment generators of generate.hpp.
#include <fmt/format.h>

#include <algorithm>
#include <numeric>

#include "t2/kernel/error.hpp"
#include "t2/gen/generate.hpp"
#include "t2/gen/random.hpp"
#include "t2/kernel/orient.hpp"
#include "t2/kernel/polygon.hpp"

namespace t2::gen {

namespace {

const Point kOrigin(1, 0, 0);

// Half of the turn around the origin a front point lies in: 0 for angles in [0, π), 1 otherwise.
int half_turn(const Point& p) { return (p.y() > 0 || (p.y() == 0 && p.x() > 0)) ? 0 : 1; }

// Angular order around the origin (exact: orient with the origin), then distance to it.
bool by_angle(const Point& p, const Point& q) {
  const int hp = half_turn(p), hq = half_turn(q);
  if (hp != hq) return hp < hq;
  const Sign s = orient(kOrigin, p, q);
  if (s != ZERO) return s > 0;
  return std::abs(p.x()) + std::abs(p.y()) < std::abs(q.x()) + std::abs(q.y());
}

void require_vertices(const Options& o) {
  if (o.n < 3) throw BadInput("a polygon needs --n of at least 3");
}

Polygon convex(const Options& o) {
  Options c = o;
  Polygon v;
  // Triples repeat now and then: draw until n distinct directions, exactly on the circle.
  for (std::uint64_t round = 0; v.size() < o.n; ++round) {
    c.seed = o.seed + round * 0x9E3779B97F4A7C15ULL;
    c.n = o.n - v.size();
    auto more = points(Kind::circle, c);
    v.insert(v.end(), more.begin(), more.end());
    std::sort(v.begin(), v.end(), [](const Point& p, const Point& q) {
      const int hp = half_turn(p), hq = half_turn(q);
      if (hp != hq) return hp < hq;
      return orient(kOrigin, p, q) > 0;
    });
    v.erase(std::unique(v.begin(), v.end()), v.end());
    if (round > 64) throw BadInput("convex-polygon: too many vertices for distinct circle points");
  }
  return v;
}

// n points in the square, in angular order around the origin. The polygon through them is
// simple when every turn from one vertex to the next, seen from the origin, is strictly between
// 0 and π (Δ(o, v_i, v_{i+1}) > 0 for all i, the last to the first included): the turns add up to
// one full turn, so the vertices go once around the origin, which lies strictly inside and sees
// every edge. Otherwise (a gap of π or more, so the origin outside, as for small n; or two
// vertices in one direction) the points are drawn again, from the same stream: a draw that
// passes is the one the generator always made.
Polygon star(const Options& o) {
  Random r(o.seed);
  for (;;) {
    Polygon v;
    while (v.size() < o.n) {
      const double x = r.symmetric(), y = r.symmetric();
      if (x == 0 && y == 0) continue;
      v.push_back(Point::cartesian(x, y));
    }
    std::sort(v.begin(), v.end(), by_angle);
    bool simple = true;
    for (std::size_t i = 0; i < v.size() && simple; ++i)
      simple = orient(kOrigin, v[i], v[(i + 1) % v.size()]) == POSITIVE;
    if (simple) return v;
  }
}

Polygon monotone(const Options& o) {
  Random r(o.seed);
  std::vector<std::pair<double, double>> lower, upper;
  std::vector<double> xs;
  for (std::size_t i = 0; i < o.n; ++i) xs.push_back(r.symmetric());
  std::sort(xs.begin(), xs.end());
  xs.erase(std::unique(xs.begin(), xs.end()), xs.end());
  Polygon v;
  // The leftmost and rightmost vertices on y = 0; the others above (upper chain) or below.
  for (std::size_t i = 0; i < xs.size(); ++i) {
    const double y = (i == 0 || i + 1 == xs.size()) ? 0.0 : 1.0 - r.unit();  // in (0, 1]
    ((i == 0 || i + 1 == xs.size() || (r.bits() & 1)) ? lower : upper).emplace_back(xs[i], y);
  }
  for (const auto& [x, y] : lower) v.push_back(Point::cartesian(x, -y));
  for (auto it = upper.rbegin(); it != upper.rend(); ++it) v.push_back(Point::cartesian(it->first, it->second));
  return v;
}

// Space partitioning (Auer and Held): a chain from a to b through the points of S, all of which
// lie strictly on one side of a ∨ b, inside a convex region that the chain does not leave.
void partition(Random& r, const Point& a, const Point& b, std::vector<Point> S, Polygon& out) {
  if (S.empty()) return;
  const Point s = S[r.below(S.size())];
  // A line through s and a point m of the segment ab separates a from b.
  for (;;) {
    const double t = 0.25 + 0.5 * r.unit();
    const Point m = Point::cartesian(a.x() + t * (b.x() - a.x()), a.y() + t * (b.y() - a.y()));
    if (orient(s, m, a) == ZERO || orient(s, m, a) == orient(s, m, b)) continue;
    std::vector<Point> A, B;
    for (const auto& p : S) {
      if (p == s) continue;
      (orient(s, m, p) == orient(s, m, a) ? A : B).push_back(p);
    }
    partition(r, a, s, std::move(A), out);
    out.push_back(s);
    partition(r, s, b, std::move(B), out);
    return;
  }
}

Polygon simple(const Options& o) {
  Random r(o.seed);
  std::vector<Point> p;
  for (std::size_t i = 0; i < o.n; ++i) {
    const double x = r.symmetric();
    p.push_back(Point::cartesian(x, r.symmetric()));
  }
  std::sort(p.begin(), p.end(), [](const Point& u, const Point& v) { return std::pair(u.x(), u.y()) < std::pair(v.x(), v.y()); });
  p.erase(std::unique(p.begin(), p.end()), p.end());
  const Point a = p.front(), b = p.back();
  std::vector<Point> below, above;
  for (std::size_t i = 1; i + 1 < p.size(); ++i) {
    const Sign s = orient(a, b, p[i]);
    if (s != ZERO) (s < 0 ? below : above).push_back(p[i]);
  }
  Polygon v{a};
  partition(r, a, b, std::move(below), v);
  v.push_back(b);
  partition(r, b, a, std::move(above), v);
  return v;
}

// 2-opt untangling (van Leeuwen and Schoone 1981; Zhu, Sundaram, Snoeyink and Mitchell 1996):
// the points in the order they were drawn make a random, tangled polygon; while two edges
// a → b and c → d that are not neighbours cross, reverse the chain b ... c between them, so that
// the edges become a → c and b → d. The crossing is proper (decided by exact orientations), so
// by the triangle inequality the perimeter strictly shrinks with each reversal: no polygon
// comes back, and the untangling ends, with a simple polygon. A contact that is no proper
// crossing (three collinear points: as good as never for random doubles) draws the points
// again from the same stream, as star-polygon does. O(n²) per pass over the edge pairs, and
// many passes: meant for the small polygons of lectures and tests (n up to a few thousand).
Polygon untangled(const Options& o) {
  Random r(o.seed);
  for (;;) {
    Polygon v;
    for (std::size_t i = 0; i < o.n; ++i) {
      const double x = r.symmetric();
      v.push_back(Point::cartesian(x, r.symmetric()));
    }
    const std::size_t n = v.size();
    bool changed = true, degenerate = false;
    while (changed && !degenerate) {
      changed = false;
      for (std::size_t i = 0; i + 2 < n && !degenerate; ++i)
        for (std::size_t j = i + 2; j < n && !degenerate; ++j) {
          if (i == 0 && j == n - 1) continue;  // neighbours through the closing edge
          const Point &a = v[i], &b = v[i + 1], &c = v[j], &d = v[(j + 1) % n];
          const Sign s1 = orient(a, b, c), s2 = orient(a, b, d), s3 = orient(c, d, a), s4 = orient(c, d, b);
          if (s1 == ZERO || s2 == ZERO || s3 == ZERO || s4 == ZERO) {
            degenerate = segments_intersect(a, b, c, d);
          } else if (s1 != s2 && s3 != s4) {
            std::reverse(v.begin() + static_cast<std::ptrdiff_t>(i + 1), v.begin() + static_cast<std::ptrdiff_t>(j + 1));
            changed = true;
          }
        }
    }
    if (degenerate || !is_simple(v)) continue;  // also repeated points, or a flat triangle
    if (orientation(v) < 0) std::reverse(v.begin(), v.end());
    return v;
  }
}

}  // namespace

Polygon polygon(Kind k, const Options& o) {
  require_vertices(o);
  switch (k) {
    case Kind::convex_polygon: return convex(o);
    case Kind::star_polygon: return star(o);
    case Kind::monotone_polygon: return monotone(o);
    case Kind::simple_polygon: return o.untangle ? untangled(o) : simple(o);
    default: throw BadInput(fmt::format("{} is not a polygon kind", name(k)));
  }
}

std::vector<Segment> segments(const Options& o) {
  // H horizontal segments y = j, x in [0, 1], and V vertical ones at distinct x in (0, 1), the
  // i-th spanning rows s_i .. s_i + c_i − 1 (its ends a quarter away from the rows): it crosses
  // exactly c_i horizontals and touches nothing else. Σ c_i = crossings.
  const std::size_t n = o.n, H = n / 2, V = n - H;
  if (o.crossings > H * V)
    throw BadInput(fmt::format("segments: {} segments allow at most {} crossings", n, H * V));
  Random r(o.seed);
  std::vector<std::size_t> c(V, 0);
  for (std::size_t left = o.crossings; left > 0;) {
    const std::size_t i = r.below(V);
    if (c[i] < H) ++c[i], --left;
  }
  std::vector<Segment> out;
  for (std::size_t j = 0; j < H; ++j) {
    const double y = static_cast<double>(j);
    out.emplace_back(Point::cartesian(0, y), Point::cartesian(1, y));
  }
  for (std::size_t i = 0; i < V; ++i) {
    const double x = (static_cast<double>(i) + 1) / static_cast<double>(V + 1);
    const std::size_t s = c[i] == H ? 0 : r.below(H - c[i] + 1);
    const double y0 = static_cast<double>(s) - 0.75, y1 = static_cast<double>(s + c[i]) - 0.25;
    out.emplace_back(Point::cartesian(x, y0), Point::cartesian(x, y1));
  }
  r.shuffle(out);
  return out;
}

}  // namespace t2::gen
