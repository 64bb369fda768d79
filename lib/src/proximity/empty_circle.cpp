// The largest empty circle of T² with a proper centre (t2/proximity/empty_circle.hpp).
#include "t2/proximity/empty_circle.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <stdexcept>

#include "t2/kernel/lexicographic.hpp"
#include "t2/triangulation/delaunay.hpp"

namespace t2 {
namespace {

using Index = EmptyCircle::Index;

/// A drawn position, exact.
struct Q {
  Rational x, y;
};

Q operator-(const Q& a, const Q& b) { return {a.x - b.x, a.y - b.y}; }
Rational dot(const Q& a, const Q& b) { return a.x * b.x + a.y * b.y; }
Rational cross(const Q& a, const Q& b) { return a.x * b.y - a.y * b.x; }
int sgn(const Rational& v) { return sgn(v.get_num()); }

/// The exact drawn positions of the front points F, computed when asked for (most sites never
/// are: a million rationals would cost more than the triangulation).
struct Positions {
  const std::vector<Point>& F;
  Q operator[](Index k) const {
    const Rational w(F[k].w());
    return {Rational(F[k].x()) / w, Rational(F[k].y()) / w};
  }
  std::size_t size() const { return F.size(); }
};

/// The best candidate so far: the largest radius, then the smallest centre (tie rule); `site`
/// a site on its circle, `other` a second one (none when not known).
struct Best {
  std::optional<Q> c;
  Rational r2;
  Index site = Triangulation::none, other = Triangulation::none;
  /// Takes z when it is better; true when it did.
  bool offer(const Q& z, const Rational& r2z, Index s, Index t = Triangulation::none) {
    if (c) {
      const int s = cmp(r2z, r2);
      if (s < 0 || (s == 0 && std::pair(cmp(z.x, c->x), cmp(z.y, c->y)) >= std::pair(0, 0))) return false;
    }
    c = z;
    r2 = r2z;
    site = s;
    other = t;
    return true;
  }
};

/// The drawn position z as an exact homogeneous point with no common factor, W > 0, then
/// mirrored to the back side (the antipode) when the sites are.
ExactPoint exact_center(const Q& z, bool mirrored) {
  Integer w;
  mpz_lcm(w.get_mpz_t(), z.x.get_den_mpz_t(), z.y.get_den_mpz_t());
  Integer x = z.x.get_num() * (w / z.x.get_den()), y = z.y.get_num() * (w / z.y.get_den());
  if (mirrored) w = -w, x = -x, y = -y;
  return ExactPoint(w, x, y);
}

/// Tells `hook` of the candidate centre z, whose radius is |r| (r = z minus a site), defined by
/// the sites `on` (`at` the report's points, `s` its sign: hook.hpp, Event::empty_circle);
/// nothing, not even |r|², for NoTrace.
template <class H>
void tell_candidate(H& hook, const Q& z, const Q& r, bool mirrored, std::initializer_list<std::size_t> at,
                    std::initializer_list<Index> on, Sign s) {
  if constexpr (trace::traced<H>) {
    EmptyCircle c;
    c.center = exact_center(z, mirrored);
    c.radius2 = dot(r, r);
    c.on_circle.assign(on.begin(), on.end());
    std::sort(c.on_circle.begin(), c.on_circle.end());
    trace::Report r = trace::about(trace::Event::empty_circle, at);
    r.circle = &c;
    r.sign = s;
    hook(r);
  }
}

/// The closed convex polygon of the hull corners H (counter-clockwise, no three collinear):
/// does it hold z? O(log h): the wedge of H[0] that holds z, then that wedge's far edge.
bool in_hull(const std::vector<Q>& H, const Q& z) {
  const std::size_t h = H.size();
  const Q v = z - H[0];
  if (sgn(cross(H[1] - H[0], v)) < 0 || sgn(cross(H[h - 1] - H[0], v)) > 0) return false;
  std::size_t lo = 1, hi = h - 1;  // z is left of H0→H[lo] (or on it), not strictly left of H0→H[hi]
  while (hi - lo > 1) {
    const std::size_t m = (lo + hi) / 2;
    (sgn(cross(H[m] - H[0], v)) >= 0 ? lo : hi) = m;
  }
  return sgn(cross(H[hi] - H[lo], z - H[lo])) >= 0;
}

/// An upper bound of the squared circumradius of the front points a, b, c, or +∞. When all
/// three have w = 1 (Cartesian doubles, no rounding yet), r² = |b−a|²|c−a|²|b−c|² / 4K², K =
/// (b−a)×(c−a). Each difference rounds once (relative u = 2⁻⁵³), each squared length then
/// twice more and the product of three twice: Ñ ≤ N(1 + 15u) and N ≤ Ñ(1 + 16u); the cross
/// product K̃ = fl(fl(t₁) − fl(t₂)), t = a product of two differences, is within 4.1u(|t̃₁| +
/// |t̃₂|) < e = 2⁻⁵⁰(|t̃₁| + |t̃₂|) of K. So K² ≥ (|K̃| − e)² when |K̃| > e, and the bound
/// Ñ·(1 + 2⁻⁴⁰) / (4(|K̃| − e)²) rounded (a few more u) is above r². Those error bounds hold
/// while nothing underflows: so a nonzero difference must be in [2⁻¹⁵⁰, 2¹⁵⁰] (then every
/// square, product and N is a normal double or +∞) and |K̃| − e at least 2⁻⁴⁰⁰; otherwise, and
/// for |w| ≠ 1, the bound is +∞ and the triangle is evaluated exactly.
double radius2_bound(const Point& a, const Point& b, const Point& c) {
  if (a.w() != 1 || b.w() != 1 || c.w() != 1) return INFINITY;
  const double bx = b.x() - a.x(), by = b.y() - a.y(), cx = c.x() - a.x(), cy = c.y() - a.y(), ex = b.x() - c.x(),
               ey = b.y() - c.y();
  for (double v : {bx, by, cx, cy, ex, ey})
    if (v != 0 && !(std::abs(v) >= 0x1p-150 && std::abs(v) <= 0x1p150)) return INFINITY;
  const double t1 = bx * cy, t2 = by * cx, K = t1 - t2, e = 0x1p-50 * (std::abs(t1) + std::abs(t2));
  if (!(std::abs(K) > e)) return INFINITY;
  const double N = (bx * bx + by * by) * (cx * cx + cy * cy) * (ex * ex + ey * ey), k = std::abs(K) - e;
  if (!(k >= 0x1p-400)) return INFINITY;
  return N * (1 + 0x1p-40) / (4 * k * k) * (1 + 0x1p-40);
}

//> largest-empty-circle
/// Algorithm 13 on the front sites `tr` (dimension 2), their exact positions `X`.
/// Each candidate is told to `hook` (NoTrace: nothing, and no trace code).
template <class Tr>
void candidates(const Triangulation& tr, const std::vector<Point>& F, const Positions& X,
                Best& best, bool mirrored, Tr& hook) {
  const auto edges = tr.hull_edges();
  std::vector<Index> after(X.size(), Triangulation::none);  // the next hull vertex
  for (auto [a, b] : edges) after[a] = b;
  std::vector<Q> H;  // the hull's corners in order (sites inside a hull edge dropped)
  Index p = edges.front().first;
  do {
    const Index a = after[p], b = after[a];
    if (sgn(cross(X[a] - X[p], X[b] - X[a])) != 0) H.push_back(X[a]);
    p = a;
  } while (p != edges.front().first);
  // The crossings: along each hull edge a → b, the cells it passes through.
  for (auto [a, b] : edges) {
    const Q D = X[b] - X[a];
    Index s = a;
    while (s != b) {
      Index next = Triangulation::none;
      Rational lambda;
      for (Index t : tr.neighbors(s)) {
        if (t == Triangulation::infinite) continue;
        const Rational den = 2 * dot(D, X[t] - X[s]);
        if (sgn(den) <= 0) continue;  // the bisector of s, t is not ahead along a → b
        const Q ta = X[t] - X[a], sa = X[s] - X[a];
        const Rational l = (dot(ta, ta) - dot(sa, sa)) / den;
        if (next == Triangulation::none || l < lambda) next = t, lambda = l;
      }
      if (next == Triangulation::none) throw std::logic_error("lec: no exit");
      const Q z{X[a].x + lambda * D.x, X[a].y + lambda * D.y};
      const Q zs = z - X[s];
      const bool better = best.offer(z, dot(zs, zs), s, next);
      tell_candidate(hook, z, zs, mirrored, {s, next, a, b}, {s, next},
                     better ? POSITIVE : ZERO);
      s = next;  // D·X[s] grows at each step: the walk ends
    }
  }
  // The Voronoi vertices: the circumcentres of the Delaunay triangles, those in the hull;
  // by an upper bound of their radius, only while it can reach the best so far.
  std::vector<std::pair<double, std::array<Index, 3>>> order;
  for (const auto& t : tr.finite_triangles()) {
    const double U = radius2_bound(F[t[0]], F[t[1]], F[t[2]]);
    if (!best.c || U >= best.r2.get_d()) order.emplace_back(U, t);  // get_d rounds to 0
  }
  std::sort(order.begin(), order.end(),
            [](const auto& l, const auto& r) { return l.first > r.first; });
  for (const auto& [U, t] : order) {
    if (best.c && U < best.r2.get_d()) break;  // U < r², and so for every later one
    const Q& a = X[t[0]];
    const Q b = X[t[1]] - a, c = X[t[2]] - a;
    const Rational d = 2 * cross(b, c), bb = dot(b, b), cc = dot(c, c);
    const Q u{(c.y * bb - b.y * cc) / d, (b.x * cc - c.x * bb) / d};  // centre − a
    const Q z{a.x + u.x, a.y + u.y};
    const bool in = in_hull(H, z), better = in && best.offer(z, dot(u, u), t[0]);
    tell_candidate(hook, z, u, mirrored, {t[0], t[1], t[2]}, {t[0], t[1], t[2]},
                   !in ? NEGATIVE : better ? POSITIVE : ZERO);
  }
}
//< largest-empty-circle

template <class H>
EmptyCircle empty_circle(std::span<const Point> P, H& hook) {
  if (P.empty()) throw BadInput("largest_empty_circle: needs at least one site");
  if (P.size() >= Triangulation::none) throw BadInput("largest_empty_circle: too many sites for 32-bit indices");
  const Index n = static_cast<Index>(P.size());
  Index front = n, back = n;
  for (Index k = 0; k < n; ++k) {
    if (P[k].w() == 0)
      throw UndefinedEmptyCircle(k, k, "a site on Omega: the hull reaches Omega, and empty circles centred in it grow "
                                       "without bound");
    (P[k].w() > 0 ? front : back) = std::min(P[k].w() > 0 ? front : back, k);
  }
  if (front < n && back < n)
    throw UndefinedEmptyCircle(front, back, "sites on both sides: the hull crosses Omega, and empty circles centred "
                                            "in it grow without bound");
  const bool mirrored = back < n;
  std::vector<Point> F(P.begin(), P.end());
  if (mirrored)
    for (Point& p : F) p = antipode(p);
  const Positions X{F};
  const Triangulation tr = delaunay(F);
  if (tr.dimension() <= 0)
    throw UndefinedEmptyCircle(0, 0, "all sites equal: the hull is one site, and no empty circle centred there has a "
                                     "positive radius");
  Best best;
  if (tr.dimension() == 2) {
    candidates(tr, F, X, best, mirrored, hook);
  } else {  // collinear: the midpoints of consecutive distinct sites along the line
    std::vector<Index> order;
    std::vector<char> dropped(n, 0);
    for (auto [d, k] : tr.duplicates()) dropped[d] = 1;
    for (Index k = 0; k < n; ++k)
      if (!dropped[k]) order.push_back(k);
    std::sort(order.begin(), order.end(), [&](Index a, Index b) { return compare_xy(F[a], F[b]) == NEGATIVE; });
    for (std::size_t m = 1; m < order.size(); ++m) {
      const Q& a = X[order[m - 1]];
      const Q& b = X[order[m]];
      const Q half{(b.x - a.x) / 2, (b.y - a.y) / 2};
      const Q z{a.x + half.x, a.y + half.y};
      const bool better = best.offer(z, dot(half, half), order[m - 1], order[m]);
      tell_candidate(hook, z, half, mirrored, {order[m - 1], order[m]}, {order[m - 1], order[m]},
           better ? POSITIVE : ZERO);
    }
  }
  EmptyCircle c;
  c.radius2 = best.r2;
  const Q& z = *best.c;
  c.center = exact_center(z, mirrored);
  // The sites on the circle: cocircular on an empty circle, so a Delaunay polygon (or edge)
  // of the sites: connected by Delaunay edges from `site`; then the sites equal to them.
  std::vector<char> on(n, 0);
  std::vector<Index> todo{best.site};
  on[best.site] = 1;
  if (best.other != Triangulation::none) on[best.other] = 1, todo.push_back(best.other);
  while (tr.dimension() == 2 && !todo.empty()) {
    const Index s = todo.back();
    todo.pop_back();
    for (Index t : tr.neighbors(s)) {
      if (t == Triangulation::infinite || on[t]) continue;
      const Q d = X[t] - z;
      if (dot(d, d) == best.r2) on[t] = 1, todo.push_back(t);
    }
  }
  for (auto [d, k] : tr.duplicates())
    if (on[k]) on[d] = 1;
  for (Index k = 0; k < n; ++k)
    if (on[k]) c.on_circle.push_back(k);
  return c;
}

}  // namespace

EmptyCircle largest_empty_circle(std::span<const Point> P) {
  NoTrace none;
  return empty_circle(P, none);
}

EmptyCircle largest_empty_circle(std::span<const Point> P, const trace::AnyHook& hook) {
  return empty_circle(P, hook);
}

}  // namespace t2
