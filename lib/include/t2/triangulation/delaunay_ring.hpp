#pragma once
/// @file delaunay_ring.hpp
/// @brief The faces of the T² Delaunay triangulation that touch Ω: one sweep of the direction
/// u once around Ω, merging the hull edges of the front sites, those of the back sites and the
/// sites on Ω (delaunay_t2.hpp states and proves what the faces are).
///
/// **Owners.** At each point [0, u] of Ω three sites may be nearest: the front owner (the front
/// hull vertex extreme in the direction u), the back owner (the back site whose drawn position
/// is extreme in −u), and the Ω owner: the site on Ω nearest in angle to u if that angle is below
/// 90° (face_disk.hpp), else none. The front owner changes at the outer normals of the front
/// hull edges, the back owner at those of the drawn back hull, the Ω owner at the middle of each
/// arc shorter than π between consecutive sites on Ω, and, across a gap of π or more, 90° after
/// the site before it (to none) and 90° before the site after it (from none).
///
/// **Faces.** While the Ω owner z exists, the Delaunay edges crossing the sweep are front–z
/// and back–z; while it is none, front–back (the band of delaunay_t2.hpp). Each change of an
/// owner makes one face from the edges before and after it, oriented front → Ω → back on the old
/// edges: a front hull edge a → b gives (b, a, z or back), a drawn back hull edge a → b gives
/// (a, b, z or front), the middle of an arc z₁ → z₂ gives (z₁, z₂, front) and (z₂, z₁, back), a
/// gap gives (front, z, back) where z stops owning and (front, back, z) where z starts. A side
/// without sites contributes v∞ as its owner: its faces are infinite (a hull exists then).

#include <algorithm>
#include <array>
#include <cstddef>
#include <vector>

#include "t2/kernel/angle.hpp"
#include "t2/kernel/point.hpp"
#include "t2/kernel/sign_sqrt.hpp"
#include "t2/triangulation/face_disk.hpp"
#include "t2/triangulation/triangulation.hpp"

namespace t2::detail {

/// The counter-clockwise boundary of a planar triangulation of front points as a cycle of
/// vertices, starting at a strict corner: the hull for dimension 2, p₀ … p_m … p₁ along the line
/// for dimension 1, the one vertex for dimension 0.
inline std::vector<Triangulation::Index> boundary_cycle(const Triangulation& t) {
  using Index = Triangulation::Index;
  std::vector<Index> c;
  if (t.dimension() == 2) {
    for (Index s = 0; s < t.size(); ++s) {  // walk the hull through the infinite triangles
      const int k = t.slot(s, Triangulation::infinite);
      if (k < 0) continue;
      Index u = s;
      do {  // (b, a, v∞) for the hull edge a → b: a is the slot after v∞'s next
        const int i = t.slot(u, Triangulation::infinite);
        c.push_back(t.vertex(u, (i + 2) % 3));
        u = t.neighbor(u, (i + 1) % 3);  // across the edge (a, v∞): the hull edge before a
      } while (u != s);
      break;
    }
    std::reverse(c.begin(), c.end());
    const auto& p = t.points();
    const std::size_t k = c.size();
    std::size_t s = 0;  // a corner: the edges before and after it are not parallel
    while (cross_of_differences(p[c[(s + k - 1) % k]], p[c[s]], p[c[s]], p[c[(s + 1) % k]]) == ZERO) ++s;
    std::rotate(c.begin(), c.begin() + static_cast<std::ptrdiff_t>(s), c.end());
    return c;
  }
  std::vector<char> dropped(t.points().size(), 0);
  for (auto [d, k] : t.duplicates()) dropped[d] = 1;
  for (Index v = 0; v < t.points().size(); ++v)
    if (!dropped[v]) c.push_back(v);
  std::sort(c.begin(), c.end(), [&](Index a, Index b) { return compare_xy(t.point(a), t.point(b)) == NEGATIVE; });
  for (std::size_t m = c.size() - 1; m-- > 1;) c.push_back(c[m]);
  return c;
}

/// One side's hull as the sweep sees it: the points (drawn), the cycle, and the output index of
/// each point. An empty cycle: no site on that side (its owner is v∞).
struct RingSide {
  const std::vector<Point>* points = nullptr;       ///< the drawn points of the side
  std::vector<Triangulation::Index> cycle;          ///< boundary_cycle of their triangulation
  std::vector<Triangulation::Index> index;          ///< output index of each point
};

/// The direction D = to − from of drawn points (w > 0); the sweep direction of its event is D
/// turned clockwise, u = (D_y, −D_x).
struct RingDir {
  const Point* from;  ///< the start of the edge
  const Point* to;    ///< the end of the edge
};

/// sign(u · z) for the sweep direction u of d and a point z of Ω (u · z = cross(z, D)).
inline Sign ring_dot(const RingDir& d, const Point& z) {
  return sign_of_poly(
      [](const auto& a, const auto& b, const auto& z) {
        return z.x * (b.y * a.w - a.y * b.w) - z.y * (b.x * a.w - a.x * b.w);
      },
      *d.from, *d.to, z);
}

/// sign(cross(z, u)) = −sign(z · D) for the sweep direction u of d and a point z of Ω.
inline Sign ring_cross(const RingDir& d, const Point& z) {
  return -sign_of_poly(
      [](const auto& a, const auto& b, const auto& z) {
        return z.x * (b.x * a.w - a.x * b.w) + z.y * (b.y * a.w - a.y * b.w);
      },
      *d.from, *d.to, z);
}

/// sign(u · ẑ₁ − u · ẑ₂): POSITIVE when the sweep direction of d is nearer in angle to z1.
inline Sign ring_nearer(const RingDir& d, const Point& z1, const Point& z2) {
  const Sign s2 = sign_of_poly(
      [](const auto& a, const auto& b, const auto& y1, const auto& y2) {
        const auto dx = b.x * a.w - a.x * b.w, dy = b.y * a.w - a.y * b.w;
        const auto u1 = y1.x * dy - y1.y * dx, u2 = y2.x * dy - y2.y * dx;
        return u1 * u1 * (y2.x * y2.x + y2.y * y2.y) - u2 * u2 * (y1.x * y1.x + y1.y * y1.y);
      },
      *d.from, *d.to, z1, z2);
  return sign_of_root_difference(ring_dot(d, z1), ring_dot(d, z2), s2);
}

/// The faces touching Ω (file comment) for the sides f, b and the points z of Ω (output indices
/// into `pts`), sorted counter-clockwise by direction without repeats; appended to `out`.
inline void ring_faces(const RingSide& f, const RingSide& b, const std::vector<Point>& pts,
                       const std::vector<Triangulation::Index>& z, std::vector<std::array<Triangulation::Index, 3>>& out) {
  using Index = Triangulation::Index;
  constexpr Index none = Triangulation::none - 1, inf = Triangulation::infinite;
  const std::size_t k = z.size();
  // The Ω events in counter-clockwise order from z[0]: kind 0 the middle of the arc z[j] z[j+1],
  // 1 the end of z[j]'s ownership before a gap, 2 the start of z[j]'s after one.
  struct OmegaEvent {
    int kind;
    std::size_t j;
  };
  std::vector<OmegaEvent> ev;
  std::vector<std::size_t> first(k);
  auto zp = [&](std::size_t j) -> const Point& { return pts[z[j % k]]; };
  for (std::size_t j = 0; j < k; ++j) {
    first[j] = ev.size();
    if (k > 1 && cross_omega(zp(j), zp(j + 1)) == POSITIVE) {
      ev.push_back({0, j});
    } else {
      ev.push_back({1, j});
      ev.push_back({2, (j + 1) % k});
    }
  }
  const std::size_t ne = ev.size();
  // A hull event: its edge, side and sort key (Ω region, half turn from ref, then the angle).
  struct Event {
    RingDir d;
    std::size_t region;
    int half;
  };
  auto make = [&](const RingDir& d, const RingDir& ref) {
    Event e{d, 0, 0};
    if (k == 0) {
      const Sign c = cross_of_differences(*ref.from, *ref.to, *d.from, *d.to);
      e.half = c == POSITIVE || (c == ZERO && dot_of_differences(*ref.from, *ref.to, *d.from, *d.to) == POSITIVE) ? 0 : 1;
      return e;
    }
    // The last z[j] at or before u in angle from z[0]; cross(z, u) = −(z · D), z · u = cross(z, D).
    const Sign c0 = ring_cross(d, zp(0));
    const int hu = c0 == POSITIVE || (c0 == ZERO && ring_dot(d, zp(0)) == POSITIVE) ? 0 : 1;
    std::size_t lo = 0, hi = k;  // invariant: z[lo] ≤ u < z[hi]
    while (hi - lo > 1) {
      const std::size_t mid = (lo + hi) / 2;
      const int hz = cross_omega(zp(0), zp(mid)) == POSITIVE ? 0 : 1;
      const bool before = hz != hu ? hz < hu : ring_cross(d, zp(mid)) != NEGATIVE;
      (before ? lo : hi) = mid;
    }
    const std::size_t j = lo, e0 = first[j];
    if (ev[e0].kind == 0)
      e.region = ring_nearer(d, zp(j), zp(j + 1)) == POSITIVE ? (e0 + ne - 1) % ne : e0;
    else if (ring_cross(d, zp(j)) != NEGATIVE && ring_dot(d, zp(j)) == POSITIVE)
      e.region = (e0 + ne - 1) % ne;  // less than 90° after z[j]
    else if (ring_cross(d, zp(j + 1)) != POSITIVE && ring_dot(d, zp(j + 1)) != NEGATIVE)
      e.region = e0 + 1;  // at most 90° before z[j+1]
    else
      e.region = e0;
    return e;
  };
  auto before = [&](const Event& a, const Event& c) {  // a strictly before c
    if (a.region != c.region) return a.region < c.region;
    if (a.half != c.half) return a.half < c.half;
    return cross_of_differences(*a.d.from, *a.d.to, *c.d.from, *c.d.to) == POSITIVE;
  };
  // The events of each side in cycle order, started after their one strict descent.
  auto side_events = [&](const RingSide& s, bool front, const RingDir* ref) {
    std::vector<Event> es;
    const std::size_t m = s.cycle.size();
    if (m < 2) return es;
    const auto& p = *s.points;
    for (std::size_t i = 0; i < m; ++i) {
      const Point &u = p[s.cycle[i]], &v = p[s.cycle[(i + 1) % m]];
      const RingDir d = front ? RingDir{&u, &v} : RingDir{&v, &u};
      es.push_back(make(d, ref ? *ref : d));
    }
    return es;
  };
  const RingDir* ref = nullptr;
  RingDir ref_dir{};
  if (k == 0 && (f.cycle.size() >= 2 || b.cycle.size() >= 2)) {
    const RingSide& s = f.cycle.size() >= 2 ? f : b;
    const auto& p = *s.points;
    ref_dir = &s == &f ? RingDir{&p[s.cycle[0]], &p[s.cycle[1]]} : RingDir{&p[s.cycle[1]], &p[s.cycle[0]]};
    ref = &ref_dir;
  }
  const auto fe = side_events(f, true, ref), be = side_events(b, false, ref);
  auto start = [&](const std::vector<Event>& es) {
    std::size_t s = 0;
    for (std::size_t i = 0; i < es.size(); ++i)
      if (before(es[i], es[(i + es.size() - 1) % es.size()])) s = i;
    return s;
  };
  const std::size_t f0 = start(fe), b0 = start(be);
  auto owner = [](const RingSide& s, std::size_t i) {
    return s.cycle.empty() ? inf : s.index[s.cycle[i % s.cycle.size()]];
  };
  Index fo = owner(f, f0), bo = owner(b, b0), zo = k > 0 ? z[0] : none;
  std::size_t i = 0, m = 0, o = 0;
  while (i < fe.size() || m < be.size() || o < ne) {
    // The next event: Ω event o precedes the hull events of its region; front before back.
    const Event* nf = i < fe.size() ? &fe[(f0 + i) % fe.size()] : nullptr;
    const Event* nb = m < be.size() ? &be[(b0 + m) % be.size()] : nullptr;
    const bool omega_next = o < ne && (!nf || nf->region >= o) && (!nb || nb->region >= o);
    if (omega_next) {
      const OmegaEvent& e = ev[o++];
      const Index zj = z[e.j];
      if (e.kind == 0) {
        const Index y = z[(e.j + 1) % k];
        out.push_back({zj, y, fo});
        out.push_back({y, zj, bo});
        zo = y;
      } else if (e.kind == 1) {
        out.push_back({fo, zj, bo});
        zo = none;
      } else {
        out.push_back({fo, bo, zj});
        zo = zj;
      }
    } else if (nf && (!nb || !before(*nb, *nf))) {
      const Index a = owner(f, f0 + i), c = owner(f, f0 + i + 1);
      out.push_back({c, a, zo != none ? zo : bo});
      fo = c;
      ++i;
    } else {
      const Index a = owner(b, b0 + m), c = owner(b, b0 + m + 1);
      out.push_back({a, c, zo != none ? zo : fo});
      bo = c;
      ++m;
    }
  }
}

}  // namespace t2::detail
