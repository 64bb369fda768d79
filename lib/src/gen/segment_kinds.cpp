// The connected and degenerate segment kinds of `t2 gen` (generate.hpp): polygon edges that
// share their endpoints, the unit edges of a grid, and segments through one point. Like every
// generator, a pure function of its options, the same bytes on every machine: no libm (the
// polygons' directions are a table of doubles), products through `scaled` so that no compiler
// fuses them.
#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "t2/gen/generate.hpp"
#include "t2/gen/random.hpp"
#include "t2/kernel/error.hpp"

namespace t2::gen {
namespace segment_kinds {

// a·b rounded once, never fused into a following sum.
double scaled(double a, double b) {
  volatile double r = a * b;
  return r;
}

// Sixteen directions round the circle, (cos, sin) of 2πk/16 to 17 digits: a table, not libm,
// so that every machine draws the same polygons.
constexpr std::array<std::array<double, 2>, 16> kDirections{{
    {1.0, 0.0}, {0.92387953251128674, 0.38268343236508978}, {0.70710678118654757, 0.70710678118654757},
    {0.38268343236508978, 0.92387953251128674}, {0.0, 1.0}, {-0.38268343236508978, 0.92387953251128674},
    {-0.70710678118654757, 0.70710678118654757}, {-0.92387953251128674, 0.38268343236508978}, {-1.0, 0.0},
    {-0.92387953251128674, -0.38268343236508978}, {-0.70710678118654757, -0.70710678118654757},
    {-0.38268343236508978, -0.92387953251128674}, {0.0, -1.0}, {0.38268343236508978, -0.92387953251128674},
    {0.70710678118654757, -0.70710678118654757}, {0.92387953251128674, -0.38268343236508978},
}};

// Polygons of 16 vertices star-shaped round uniform centres, radii 0.05 to 0.3, each vertex's
// radius varied by up to 40 %: the edges of one polygon meet end to end, and polygons cross.
// The last polygon is an open chain when 16 does not divide n.
std::vector<Segment> polygon_edges(const Options& o) {
  Random r(o.seed);
  std::vector<Segment> out;
  while (out.size() < o.n) {
    const double cx = r.symmetric(), cy = r.symmetric(), rho = 0.05 + scaled(0.25, r.unit());
    std::vector<Point> v;
    for (std::size_t k = 0; k < 16; ++k) {
      const double s = scaled(rho, 0.6 + scaled(0.4, r.unit()));
      v.push_back(Point::cartesian(cx + scaled(s, kDirections[k][0]), cy + scaled(s, kDirections[k][1])));
    }
    for (std::size_t k = 0; k < 16 && out.size() < o.n; ++k) out.emplace_back(v[k], v[(k + 1) % 16]);
  }
  return out;
}

// The unit edges of the m×m grid of integer points, m the smallest with 2m(m − 1) ≥ n, n of them
// drawn at random: an inner point ends up to four segments, neighbours on a line touch end to end.
std::vector<Segment> segment_grid(const Options& o) {
  std::size_t m = 2;
  while (2 * m * (m - 1) < o.n) ++m;
  std::vector<Segment> all;
  for (std::size_t i = 0; i < m; ++i)
    for (std::size_t j = 0; j < m; ++j) {
      const double x = static_cast<double>(i), y = static_cast<double>(j);
      if (i + 1 < m) all.emplace_back(Point::cartesian(x, y), Point::cartesian(x + 1, y));
      if (j + 1 < m) all.emplace_back(Point::cartesian(x, y), Point::cartesian(x, y + 1));
    }
  Random r(o.seed);
  r.shuffle(all);
  all.erase(all.begin() + static_cast<std::ptrdiff_t>(o.n), all.end());
  return all;
}

// n segments through the origin: from a random dyadic point a ≠ 0 of [-1, 1]² to −2^-j a,
// j in 0 … 3 (exact: a power of two), so the origin lies exactly inside every one of them.
std::vector<Segment> through_point(const Options& o) {
  Random r(o.seed);
  std::vector<Segment> out;
  while (out.size() < o.n) {
    const double x = r.symmetric(), y = r.symmetric();
    if (x == 0 && y == 0) continue;
    const double f = -1.0 / static_cast<double>(std::uint64_t{1} << r.below(4));
    out.emplace_back(Point::cartesian(x, y), Point::cartesian(f * x, f * y));
  }
  return out;
}

}  // namespace segment_kinds

std::vector<Segment> segments(Kind k, const Options& o) {
  switch (k) {
    case Kind::segments: return segments(o);
    case Kind::polygon_edges: return segment_kinds::polygon_edges(o);
    case Kind::segment_grid: return segment_kinds::segment_grid(o);
    case Kind::segments_through_point: return segment_kinds::through_point(o);
    default: throw BadInput(fmt::format("{} is not a segment kind", name(k)));
  }
}

bool is_segment_kind(Kind k) {
  return k == Kind::segments || k == Kind::polygon_edges || k == Kind::segment_grid ||
         k == Kind::segments_through_point;
}

}  // namespace t2::gen
