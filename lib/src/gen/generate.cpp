// The input generators of generate.hpp: point kinds, 3-D kinds and the text of `t2 gen`.
// Floating-point steps use only +, −, ×, ÷ and √ (correctly rounded by IEEE 754, so the same on
// every machine); products feeding a sum go through `product`, so that no compiler contracts
// them into a fused multiply-add that another machine would not use.
#include "t2/gen/generate.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "t2/kernel/error.hpp"
#include "t2/gen/random.hpp"
#include "t2/kernel/number.hpp"
#include "t2/kernel/orient.hpp"

namespace t2::gen {

namespace {

struct Info {
  Kind kind;
  const char* name;
  const char* what;
};

const Info kInfo[] = {
    {Kind::uniform, "uniform", "uniform in the square [-1,1)^2"},
    {Kind::disk, "disk", "uniform in the open unit disk"},
    {Kind::polygon_interior, "polygon-interior", "uniform in the L-shaped polygon (-1,-1) (1,-1) (1,0) (0,0) (0,1) (-1,1)"},
    {Kind::normal, "normal", "--clusters normal clusters, sigma 0.1 (Irwin-Hall), around uniform centres"},
    {Kind::kuzmin, "kuzmin", "Kuzmin's distribution (PBBS): heavy tails around the origin"},
    {Kind::circle, "circle", "exactly on the unit circle: [c, a, b] with a^2+b^2 = c^2 (--cartesian: rounded a/c b/c)"},
    {Kind::segment, "segment", "exactly on the line y = x/2 + 1/4, x in [-1,1] (dyadic coordinates)"},
    {Kind::boundary, "boundary", "exactly on the boundary of the square [-1,1]^2 (dyadic coordinates)"},
    {Kind::grid, "grid", "integer points of the m x m grid, m = ceil(sqrt(n)), drawn with repetition"},
    {Kind::duplicates, "duplicates", "n/8 distinct points, repeated, written with scales 1, 2, 4"},
    {Kind::both_sides, "both-sides", "front and back points (--back share behind), hull crossing Omega"},
    {Kind::antipodal, "antipodal", "front points plus the antipodes of a tenth of them (no hull)"},
    {Kind::infinity, "infinity", "half front points, half at infinity in directions with dx > 0"},
    {Kind::circle_both_sides, "circle-both-sides", "exactly on a circle around the Omega point [0,1,0]: [a, c, b] with a^2+b^2 = c^2, both sides"},
    {Kind::cube, "cube", "3-D: uniform in the cube [-1,1)^3 (lines x y z)"},
    {Kind::sphere, "sphere", "3-D: on the unit sphere, rounded (lines x y z)"},
    {Kind::simple_polygon, "simple-polygon", "a random simple polygon (space partitioning; --untangle: 2-opt)"},
    {Kind::star_polygon, "star-polygon", "a polygon star-shaped around the origin"},
    {Kind::convex_polygon, "convex-polygon", "a convex polygon, vertices exactly on the unit circle"},
    {Kind::monotone_polygon, "monotone-polygon", "an x-monotone polygon"},
    {Kind::segments, "segments", "n segments with exactly --crossings proper crossings"},
    {Kind::polygon_edges, "polygon-edges", "the edges of random 16-gons: shared endpoints, polygons crossing"},
    {Kind::segment_grid, "segment-grid", "n unit edges of an m x m integer grid: up to four segments end at a point"},
    {Kind::segments_through_point, "segments-through-point", "n segments through the origin, exactly: one point on all"},
};

const Info& info(Kind k) {
  for (const auto& i : kInfo)
    if (i.kind == k) return i;
  throw BadInput("unknown generator kind");
}

// A rounded product that the compiler may not fuse with a following sum.
double product(double a, double b) {
  volatile double r = a * b;
  return r;
}

// A uniform integer pair in the disk of radius 2^bits (exclusive), not the origin; bits ≤ 31,
// so that a² + b² is exact in 64 bits.
std::pair<std::int64_t, std::int64_t> in_int_disk(Random& r, int bits) {
  const std::uint64_t span = std::uint64_t{1} << (bits + 1);
  const std::int64_t half = std::int64_t{1} << bits;
  for (;;) {
    const std::int64_t a = static_cast<std::int64_t>(r.below(span)) - half;
    const std::int64_t b = static_cast<std::int64_t>(r.below(span)) - half;
    const auto s = static_cast<std::uint64_t>(a * a) + static_cast<std::uint64_t>(b * b);
    if (s != 0 && s < static_cast<std::uint64_t>(half) * static_cast<std::uint64_t>(half)) return {a, b};
  }
}

// A dyadic number k·2^-30, k uniform in [-2^30, 2^30]: exactly in [-1, 1].
double dyadic(Random& r) {
  return static_cast<double>(static_cast<std::int64_t>(r.below((std::uint64_t{1} << 31) + 1)) - (std::int64_t{1} << 30)) * 0x1p-30;
}

// A point exactly on the unit circle: [c, a, b] from the Pythagorean triple of (m, k).
Point on_circle(Random& r, bool cartesian) {
  std::int64_t m = 0, k = 0;
  while (m == 0 && k == 0) {
    m = static_cast<std::int64_t>(r.below(4096));
    k = static_cast<std::int64_t>(r.below(4096));
  }
  double a = static_cast<double>(m * m - k * k), b = static_cast<double>(2 * m * k);
  const double c = static_cast<double>(m * m + k * k);
  if (r.bits() & 1) a = -a, b = -b;  // the triple covers angles in [0, π]; the sign the rest
  if (cartesian) return Point::cartesian(a / c, b / c);
  return Point(c, a, b);
}

std::vector<Point> make_points(Kind k, const Options& o) {
  Random r(o.seed);
  std::vector<Point> out;
  out.reserve(o.n);
  const std::size_t n = o.n;
  switch (k) {
    case Kind::uniform:
      for (std::size_t i = 0; i < n; ++i) {
        const double x = r.symmetric();
        out.push_back(Point::cartesian(x, r.symmetric()));
      }
      break;
    case Kind::disk:
      for (std::size_t i = 0; i < n; ++i) {
        const auto [a, b] = in_int_disk(r, 31);  // dyadic k·2⁻³¹, exactly inside
        out.push_back(Point::cartesian(static_cast<double>(a) * 0x1p-31, static_cast<double>(b) * 0x1p-31));
      }
      break;
    case Kind::polygon_interior:
      while (out.size() < n) {
        const double x = r.symmetric(), y = r.symmetric();
        if (!(x >= 0 && y >= 0)) out.push_back(Point::cartesian(x, y));
      }
      break;
    case Kind::normal: {
      if (o.clusters == 0) throw BadInput("normal: --clusters must be at least 1");
      std::vector<std::pair<double, double>> centre(o.clusters);
      for (auto& c : centre) {
        c.first = r.symmetric();
        c.second = r.symmetric();
      }
      for (std::size_t i = 0; i < n; ++i) {
        const auto& c = centre[r.below(o.clusters)];
        const double dx = product(0.1, r.normal());
        const double dy = product(0.1, r.normal());
        out.push_back(Point::cartesian(c.first + dx, c.second + dy));
      }
      break;
    }
    case Kind::kuzmin:
      for (std::size_t i = 0; i < n; ++i) {
        const auto [a, b] = in_int_disk(r, 26);  // a² + b² < 2⁵²: exact in a double
        const double rho = std::sqrt(static_cast<double>(a * a + b * b));
        const double s = 1.0 - r.unit();  // in (0, 1]
        const double radius = std::sqrt(1.0 / product(s, s) - 1.0);
        const double f = radius / rho;
        out.push_back(Point::cartesian(product(f, static_cast<double>(a)), product(f, static_cast<double>(b))));
      }
      break;
    case Kind::circle:
      for (std::size_t i = 0; i < n; ++i) out.push_back(on_circle(r, o.cartesian));
      break;
    case Kind::circle_both_sides:  // the unit circle's points [c, a, b] as [a, c, b]: w = a changes sign
      for (std::size_t i = 0; i < n; ++i) {
        const Point p = on_circle(r, false);
        out.push_back(Point(p.x(), p.w(), p.y()));
      }
      break;
    case Kind::segment:
      for (std::size_t i = 0; i < n; ++i) {
        const double x = dyadic(r);
        out.push_back(Point::cartesian(x, x * 0.5 + 0.25));  // exact: x has 31 bits at most
      }
      break;
    case Kind::boundary:
      for (std::size_t i = 0; i < n; ++i) {
        const double t = dyadic(r);
        switch (r.below(4)) {
          case 0: out.push_back(Point::cartesian(t, -1)); break;
          case 1: out.push_back(Point::cartesian(1, t)); break;
          case 2: out.push_back(Point::cartesian(t, 1)); break;
          default: out.push_back(Point::cartesian(-1, t)); break;
        }
      }
      break;
    case Kind::grid: {
      std::uint64_t m = 2;
      while (m * m < n) ++m;
      for (std::size_t i = 0; i < n; ++i) {
        const double x = static_cast<double>(r.below(m));
        out.push_back(Point::cartesian(x, static_cast<double>(r.below(m))));
      }
      break;
    }
    case Kind::duplicates: {
      std::vector<Point> pool;
      for (std::size_t i = 0; i < std::max<std::size_t>(1, n / 8); ++i) {
        const double x = r.symmetric();
        pool.push_back(Point::cartesian(x, r.symmetric()));
      }
      for (std::size_t i = 0; i < n; ++i) {
        const Point& p = pool[r.below(pool.size())];
        const double s = static_cast<double>(1 << r.below(3));  // exact rescaling: the same point
        out.push_back(Point(s, s * p.x(), s * p.y()));
      }
      break;
    }
    case Kind::both_sides: {
      if (!(o.back >= 0 && o.back <= 1)) throw BadInput("both-sides: --back must lie in [0, 1]");
      // Front points have x < c, back points (drawn at (x, y)) have x > c: all lie in the open
      // hemisphere c·w − x > 0, so the hull exists; it crosses Ω when both sides are present.
      const double c = 1.0 - 2.0 * o.back;
      const auto behind = static_cast<std::size_t>(std::llround(o.back * static_cast<double>(n)));
      for (std::size_t i = 0; i < n; ++i) {
        const bool back = i < behind;
        double x = r.symmetric();
        while (back ? !(x > c) : !(x < c)) x = r.symmetric();
        const double y = r.symmetric();
        out.push_back(back ? Point(-1, -x, -y) : Point::cartesian(x, y));
      }
      r.shuffle(out);
      break;
    }
    case Kind::antipodal: {
      if (n < 2) throw BadInput("antipodal: --n must be at least 2 (a point and its antipode)");
      const std::size_t pairs = std::max<std::size_t>(1, n / 10);
      for (std::size_t i = 0; i < n - pairs; ++i) {
        const double x = r.symmetric();
        out.push_back(Point::cartesian(x, r.symmetric()));
      }
      // The antipodes of `pairs` distinct front points, drawn without replacement (a partial
      // Fisher–Yates): drawn with replacement, a point chosen twice gave two equal antipodes.
      const std::size_t front = n - pairs;
      for (std::size_t i = 0; i < pairs; ++i) {
        std::swap(out[i], out[i + r.below(front - i)]);
        out.push_back(antipode(out[i]));
      }
      r.shuffle(out);
      break;
    }
    case Kind::infinity:
      // Front points in [-1, 1)² and directions with dx > 0 lie in the hemisphere 2w + x > 0.
      for (std::size_t i = 0; i < n; ++i) {
        if (i % 2 == 0) {
          const double x = r.symmetric();
          out.push_back(Point::cartesian(x, r.symmetric()));
        } else {
          const double dx = 1.0 - r.unit();
          out.push_back(Point::at_infinity(dx, r.symmetric()));
        }
      }
      break;
    default:
      throw BadInput(fmt::format("{} is not a point kind", name(k)));
  }
  return out;
}

}  // namespace

const std::vector<Kind>& all_kinds() {
  static const std::vector<Kind> v = [] {
    std::vector<Kind> k;
    for (const auto& i : kInfo) k.push_back(i.kind);
    return k;
  }();
  return v;
}

std::string_view name(Kind k) { return info(k).name; }
std::string_view description(Kind k) { return info(k).what; }

Kind kind_from_name(std::string_view s) {
  std::string names;
  for (const auto& i : kInfo) {
    if (s == i.name) return i.kind;
    names += names.empty() ? "" : ", ";
    names += i.name;
  }
  throw BadInput(fmt::format("unknown kind '{}' (one of: {})", s, names));
}

std::vector<Point> points(Kind k, const Options& o) { return make_points(k, o); }

std::vector<std::array<double, 3>> points3(Kind k, const Options& o) {
  Random r(o.seed);
  std::vector<std::array<double, 3>> out;
  out.reserve(o.n);
  if (k == Kind::cube) {
    for (std::size_t i = 0; i < o.n; ++i) {
      const double x = r.symmetric(), y = r.symmetric();
      out.push_back({x, y, r.symmetric()});
    }
  } else if (k == Kind::sphere) {
    const std::int64_t half = std::int64_t{1} << 26;
    while (out.size() < o.n) {
      std::int64_t c[3];
      for (auto& v : c) v = static_cast<std::int64_t>(r.below(std::uint64_t{1} << 27)) - half;
      const std::int64_t s = c[0] * c[0] + c[1] * c[1] + c[2] * c[2];  // < 3·2⁵², exact
      if (s >= half * half || s < (half / 64) * (half / 64)) continue;  // in the ball, not near 0
      const double rho = std::sqrt(static_cast<double>(s));
      out.push_back({static_cast<double>(c[0]) / rho, static_cast<double>(c[1]) / rho, static_cast<double>(c[2]) / rho});
    }
  } else {
    throw BadInput(fmt::format("{} is not a 3-D kind", name(k)));
  }
  return out;
}

}  // namespace t2::gen
