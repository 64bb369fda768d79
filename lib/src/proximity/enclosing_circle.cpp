// The smallest enclosing circle by Welzl's algorithm (t2/proximity/enclosing_circle.hpp).
#include "t2/proximity/enclosing_circle.hpp"

#include <algorithm>
#include <array>
#include <limits>
#include <random>

#include "t2/kernel/circle.hpp"
#include "t2/kernel/filter.hpp"
#include "t2/kernel/incircle.hpp"
#include "enclosing_disk.hpp"

namespace t2 {
namespace detail {

//> in-diameter-disk
/// The side of p relative to the closed disk with diameter ab (proper points of one
/// side): POSITIVE inside, ZERO on the circle, NEGATIVE outside. It is
/// −sign((P − A)·(P − B)); the homogeneous form below differs by p_w²·a_w·b_w > 0.
Sign in_diameter_disk(const Point& a, const Point& b, const Point& p) {
  return -sign_of_poly(
      [](const auto& a, const auto& b, const auto& p) {
        return (p.x * a.w - a.x * p.w) * (p.x * b.w - b.x * p.w) +
               (p.y * a.w - a.y * p.w) * (p.y * b.w - b.y * p.w);
      },
      a, b, p);
}
//< in-diameter-disk

/// The side of q relative to the closed disk of d (POSITIVE inside, ZERO on, NEGATIVE out).
Sign side(const Disk& d, const Point& q) {
  if (d.k == 3) return in_circle(d.p[0], d.p[1], d.p[2], q);
  if (d.k == 2) return in_diameter_disk(d.p[0], d.p[1], q);
  return q == d.p[0] ? ZERO : NEGATIVE;
}

}  // namespace detail

namespace {

using namespace detail;
using Index = EnclosingCircle::Index;

/// The points in the order of the algorithm, with their input indices: a Fisher–Yates shuffle
/// with a fixed seed (header). The points themselves are moved, so the scans read memory in order.
void shuffle(std::vector<Point>& P, std::vector<Index>& id) {
  const Index n = static_cast<Index>(P.size());
  id.resize(n);
  for (Index i = 0; i < n; ++i) id[i] = i;
  std::mt19937_64 rng(0x5ec'c1'2c1e);
  for (Index i = n; i > 1; --i) {
    const Index r = static_cast<Index>(rng() % i);
    std::swap(P[i - 1], P[r]);
    std::swap(id[i - 1], id[r]);
  }
}

/// Is site i (at p) strictly outside d? Told to the hook with the test's sign.
template <class H>
bool outside(const Disk& d, const Point& p, Index i, H& hook) {
  const Sign s = side(d, p);
  tell(hook, trace::Event::in_disk, {std::size_t(i)}, {}, s);
  return s == NEGATIVE;
}

/// d, told to the hook as the new disk.
template <class H>
Disk enclose(const Disk& d, H& hook) {
  tell(hook, [&] {
    trace::Report r;
    r.event = trace::Event::enclose;
    for (int m = 0; m < d.k; ++m) r.at[m] = d.s[m];
    return r;
  });
  return d;
}

//> welzl
/// Welzl's algorithm on the front points P, in their order (de Berg et al.'s three
/// loops): the disk of the first i sites; when site i is outside it, the smallest
/// disk with site i on its boundary, found by the same scan with one, then two sites
/// fixed. id[i] is the input index of P[i]; `hook` hears every test and every disk.
template <class H>
Disk welzl(const std::vector<Point>& P, const std::vector<Index>& id, H& hook) {
  const Index n = static_cast<Index>(P.size());
  if (n == 1) return enclose(Disk{{P[0], P[0], P[0]}, {id[0], id[0], id[0]}, 1}, hook);
  Disk d = enclose(diameter(P[0], id[0], P[1], id[1]), hook);
  for (Index i = 2; i < n; ++i) {
    if (!outside(d, P[i], id[i], hook)) continue;
    d = enclose(diameter(P[i], id[i], P[0], id[0]), hook);  // site i is on the circle
    for (Index j = 1; j < i; ++j) {
      if (!outside(d, P[j], id[j], hook)) continue;
      d = enclose(diameter(P[i], id[i], P[j], id[j]), hook);  // and so is site j
      for (Index k = 0; k < j; ++k)
        if (outside(d, P[k], id[k], hook))  // and site k
          d = enclose(circumcircle(P[i], id[i], P[j], id[j], P[k], id[k]), hook);
    }
  }
  return d;
}
//< welzl

/// The centre of d with exact integers and no division, reduced (no common factor).
ExactPoint center_of(const Disk& d) {
  ExactPoint c = to_exact(d.p[0]);
  if (d.k == 2) {
    const ExactPoint a = to_exact(d.p[0]), b = to_exact(d.p[1]);
    c = mix(Integer(abs(b.w())), a, Integer(abs(a.w())), b);  // the midpoint, on their side
  } else if (d.k == 3) {
    c = circle_through(to_exact(d.p[0]), to_exact(d.p[1]), to_exact(d.p[2])).center();
  }
  Integer g;
  mpz_gcd(g.get_mpz_t(), c.w().get_mpz_t(), c.x().get_mpz_t());
  mpz_gcd(g.get_mpz_t(), g.get_mpz_t(), c.y().get_mpz_t());
  return ExactPoint(Integer(c.w() / g), Integer(c.x() / g), Integer(c.y() / g));
}

/// |C − A|² for the centre c and a proper point a of its side, exactly.
Rational squared_radius(const ExactPoint& c, const ExactPoint& a) {
  const Integer dx = c.x() * a.w() - a.x() * c.w(), dy = c.y() * a.w() - a.y() * c.w(), ww = c.w() * a.w();
  Rational r(Integer(dx * dx + dy * dy), Integer(ww * ww));
  r.canonicalize();
  return r;
}

/// smallest_enclosing_circle, telling `hook` (NoTrace: nothing, and no trace code).
template <class H>
EnclosingCircle enclosing_circle(std::span<const Point> points, H& hook) {
  const Sign sigma = enclosing_side(points);
  // Back sites: their drawn positions (antipodes), and the antipode of their answer.
  std::vector<Point> P = drawn_sites(points, sigma);
  std::vector<Index> id;
  shuffle(P, id);
  return enclosing_answer(P, id, welzl(P, id, hook), sigma);
}

}  // namespace

namespace detail {

Sign enclosing_side(std::span<const Point> points) {
  if (points.empty()) throw BadInput("the smallest enclosing circle needs at least one site");
  if (points.size() >= std::numeric_limits<Index>::max())
    throw BadInput("the smallest enclosing circle takes at most 2^32 - 2 sites");
  const Index n = static_cast<Index>(points.size());
  // The definition of T² (header): proper sites, all on one side. Sites on both sides first
  // (an Ω site changes nothing there), then a site on Ω.
  Index front = n, back = n, omega = n;
  for (Index i = n; i-- > 0;) (points[i].w() > 0 ? front : points[i].w() < 0 ? back : omega) = i;
  if (front < n && back < n)
    throw UndefinedEnclosing(front, back,
                             "the smallest enclosing circle is undefined for sites on both sides (front site " +
                                 std::to_string(front) + ", back site " + std::to_string(back) +
                                 "): every proper centre is beyond infinity from a side, and moving it away "
                                 "shrinks that radius towards +inf without end");
  if (omega < n)
    throw UndefinedEnclosing(omega, omega,
                             "the smallest enclosing circle is undefined with site " + std::to_string(omega) +
                                 " on Omega: every centre on the side of the proper sites (on either side if there "
                                 "are none) has radius +inf, so no circle is the smallest");
  return front < n ? POSITIVE : NEGATIVE;
}

std::vector<Point> drawn_sites(std::span<const Point> points, Sign sigma) {
  std::vector<Point> P(points.begin(), points.end());
  if (sigma == NEGATIVE)
    for (Point& p : P) p = antipode(p);
  return P;
}

EnclosingCircle enclosing_answer(const std::vector<Point>& P, const std::vector<Index>& id, const Disk& d,
                                 Sign sigma) {
  EnclosingCircle c;
  c.center = center_of(d);
  c.radius2 = squared_radius(c.center, to_exact(d.p[0]));
  std::vector<std::pair<Index, Point>> on;  // the sites on the circle, by input index
  for (Index i = 0; i < P.size(); ++i)
    if (side(d, P[i]) == ZERO) on.emplace_back(id.empty() ? i : id[i], P[i]);
  std::sort(on.begin(), on.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  // The support: Welzl's run (the same shuffle) on the sites of the circle alone, in input
  // order. Their smallest circle is d (its centre is in their hull, chapter 12), so the
  // support defines d, and it depends on the set of sites on d only, not on how d was found.
  std::vector<Point> Q;
  for (const auto& [i, p] : on) {
    c.on_circle.push_back(i);
    Q.push_back(p);
  }
  std::vector<Index> qid;
  shuffle(Q, qid);
  NoTrace none;
  const Disk e = welzl(Q, qid, none);
  for (int m = 0; m < e.k; ++m) c.support.push_back(c.on_circle[e.s[m]]);
  std::sort(c.support.begin(), c.support.end());
  if (sigma == NEGATIVE) c.center = antipode(c.center);
  return c;
}

}  // namespace detail

EnclosingCircle smallest_enclosing_circle(std::span<const Point> points) {
  NoTrace none;
  return enclosing_circle(points, none);
}

EnclosingCircle smallest_enclosing_circle(std::span<const Point> points,
                                          const trace::AnyHook& hook) {
  return enclosing_circle(points, hook);
}

}  // namespace t2
