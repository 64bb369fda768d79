#pragma once
// The sites and the circle events of Fortune's sweep (fortune.cpp) and their exact order: a
// site's coordinates, the enclosures of an event's y, its rationals made on demand, and the
// comparisons of events with sites and with each other (the filters first: enclosures, exact
// stages on doubles in fortune_exact.hpp, equal circles by in_circle; rationals last). Private
// to lib/src/voronoi.

#include <memory>
#include <vector>

#include "fortune_beach.hpp"
#include "fortune_exact.hpp"
#include "fortune_interval.hpp"
#include "t2/kernel/incircle.hpp"
#include "t2/kernel/number.hpp"
#include "t2/kernel/point.hpp"
#include "t2/kernel/sign_sqrt.hpp"
#include "t2/voronoi/fortune.hpp"

namespace t2::detail::fortune_sweep {

using Index = FortuneDiagram::Index;

//> fortune-root-sign
/// sign(a + b√c) for rationals, c ≥ 0: times the positive a.den · b.den · c.den it is
/// A + B√C with A = a.num·b.den·c.den, B = b.num·a.den, C = c.num·c.den (integers), whose sign
/// sign_of_root_sum decides (k = 1 makes A² and B²C of one total degree).
inline Sign root_sign(const Rational& a, const Rational& b, const Rational& c) {
  const Integer A = a.get_num() * b.get_den() * c.get_den(), B = b.get_num() * a.get_den(),
                C = c.get_num() * c.get_den(), k(1);
  return sign_of_root_sum([](const auto& A, const auto&, const auto&, const auto& k) { return A * k; },
                          [](const auto&, const auto& B, const auto&, const auto&) { return B; },
                          [](const auto&, const auto&, const auto& C, const auto& k) { return C * k; }, A, B, C, k);
}
//< fortune-root-sign

/// A site: x/w and y/w as doubles (exact when `exact`: w = 1), its point and its index in the
/// input. The rationals x/w, y/w are made only by the exact stages (`qx`, `qy`).
struct Site {
  double x, y;
  Interval xi, yi;  // enclosures of x/w and y/w (fortune_interval.hpp)
  Point p;
  Index id;
  bool exact;
};

/// x/w and y/w of a site as rationals.
inline Rational qx(const Site& s) { return s.exact ? Rational(s.x) : Rational(s.p.x()) / Rational(s.p.w()); }
inline Rational qy(const Site& s) { return s.exact ? Rational(s.y) : Rational(s.p.y()) / Rational(s.p.w()); }

/// sign(y_a − y_b), then sign(x_a − x_b) when `by_x` and the ordinates are equal: exact.
/// (Else the enclosures, then sign(y_a w_b − y_b w_a) of the homogeneous coordinates, w > 0.)
inline int compare_sites(const Site& a, const Site& b, bool by_x) {
  if (a.exact && b.exact) {
    if (a.y != b.y) return a.y < b.y ? -1 : 1;
    return !by_x || a.x == b.x ? 0 : a.x < b.x ? -1 : 1;
  }
  if (a.yi.hi < b.yi.lo) return -1;
  if (a.yi.lo > b.yi.hi) return 1;
  if (const int c = sign_of_poly([](const auto& p, const auto& q) { return p.y * q.w - q.y * p.w; }, a.p, b.p);
      c != 0 || !by_x)
    return c;
  if (a.xi.hi < b.xi.lo) return -1;
  if (a.xi.lo > b.xi.hi) return 1;
  return sign_of_poly([](const auto& p, const auto& q) { return p.x * q.w - q.x * p.w; }, a.p, b.p);
}

/// A circle event: the circle through the sites a, b, c with centre (cx, cy) and squared
/// radius R, at y = cy + √R. The rationals are computed when a decision first needs them
/// (`exact`); the enclosure `yi` of cy + √R, from the sites' enclosures, decides most orders.
struct Event {
  const Site *a, *b, *c;
  mutable Interval yi;  // narrowed once by `tight`
  Arc* arc;     // the arc it removes
  bool valid;   // false once the arc or its neighbours changed
  mutable bool tightened;  // `tight` ran
  mutable int circle;  // union-find: an event known to be on the same circle (itself at first)
  struct Circle {
    Rational cx, cy, R;
  };
  mutable std::unique_ptr<Circle> known{};  // the rationals, once computed
};

/// The event's y enclosed tightly, once, when the enclosure `yi` did not decide: `yi` becomes
/// its intersection with tight_event_y's (fortune_exact.hpp; sites with w = 1), both enclosures.
inline const Interval& tight(const Event& e) {
  if (!e.tightened) {
    e.tightened = true;
    if (e.a->exact && e.b->exact && e.c->exact) {
      const Interval t = detail::tight_event_y(e.a->x, e.a->y, e.b->x, e.b->y, e.c->x, e.c->y);
      e.yi = {std::max(t.lo, e.yi.lo), std::min(t.hi, e.yi.hi)};
    }
  }
  return e.yi;
}

/// The centre and squared radius of the circle through a, b, c (not collinear), as rationals.
inline const Event::Circle& exact(const Event& e) {
  if (e.known) return *e.known;
  const Site &a = *e.a, &b = *e.b, &c = *e.c;
  const Rational ax = qx(a), ay = qy(a);
  const Rational bx = qx(b) - ax, by = qy(b) - ay, cx = qx(c) - ax, cy = qy(c) - ay;
  const Rational D = 2 * (bx * cy - by * cx), B = bx * bx + by * by, C = cx * cx + cy * cy;
  const Rational ux = (cy * B - by * C) / D, uy = (bx * C - cx * B) / D;
  e.known = std::make_unique<Event::Circle>(Event::Circle{ax + ux, ay + uy, ux * ux + uy * uy});
  return *e.known;
}

/// The enclosure of the event's y, cy + √R, by the same formula in intervals.
inline Interval event_y(const Site& a, const Site& b, const Site& c) {
  const Interval bx = b.xi - a.xi, by = b.yi - a.yi, cx = c.xi - a.xi, cy = c.yi - a.yi;
  const Interval D = bx * cy - by * cx, B = bx * bx + by * by, C = cx * cx + cy * cy;
  const Interval h = recip(D + D);
  const Interval ux = (cy * B - by * C) * h, uy = (bx * C - cx * B) * h;
  return (a.yi + uy + sqrt(ux * ux + uy * uy)).settled();
}

/// The representative of event i's class of events on one circle (path halving).
inline int circle_of(const std::vector<Event>& evs, int i) {
  while (evs[i].circle != i) i = evs[i].circle = evs[evs[i].circle].circle;
  return i;
}

/// True when the sites of f lie on the circle of e (exact: the filtered in_circle).
inline bool same_circle(const Event& e, const Event& f) {
  for (const Site* x : {f.a, f.b, f.c})
    if (x != e.a && x != e.b && x != e.c && in_circle(e.a->p, e.b->p, e.c->p, x->p) != ZERO) return false;
  return true;
}

/// When the circle of f is the circle of e moved by (t, 0) (lattices: rows of equal circles),
/// the events have one y and sign(e − f) = sign(−t); when it is the mirror image of e's circle
/// in a vertical line x = S/2 (inputs symmetric left to right), one y and sign(e − f) =
/// sign(2cₓ − S) (centre_x_vs): that sign; else 2 (not decided). Exact: t (or S) is an exact
/// difference (sum) of abscissae of a site of f and a site of e on one row, and the other sites
/// of f, moved back (reflected back: S − x), exact, are on the circle of e (the filtered
/// in_circle). A circle is the one through three of its points, so the circles are images.
inline int translated(const Event& e, const Event& f) {
  for (const Site* s : {e.a, e.b, e.c, f.a, f.b, f.c})
    if (!s->exact) return 2;
  const Site* F[3] = {f.a, f.b, f.c};
  for (const Site* x : {e.a, e.b, e.c})
    for (int j = 0; j < 3; ++j) {
      double t;
      if (x->y != F[j]->y || !detail::exact_difference(F[j]->x, x->x, t)) continue;
      bool on = true;
      for (int k = 0; k < 3 && on; ++k) {
        double b;
        on = k == j || (detail::exact_difference(F[k]->x, t, b) &&
                        in_circle(e.a->p, e.b->p, e.c->p, Point(1, b, F[k]->y)) == ZERO);
      }
      if (on) return t > 0 ? -1 : t < 0 ? 1 : 0;
      double S;
      if (!detail::exact_difference(F[j]->x, -x->x, S)) continue;
      on = true;
      for (int k = 0; k < 3 && on; ++k) {
        double b;
        on = k == j || (detail::exact_difference(S, F[k]->x, b) &&
                        in_circle(e.a->p, e.b->p, e.c->p, Point(1, b, F[k]->y)) == ZERO);
      }
      if (on) return detail::centre_x_vs(e.a->x, e.a->y, e.b->x, e.b->y, e.c->x, e.c->y, S);
    }
  return 2;
}

//> fortune-event-order
/// The order of events: sign(e − site) by y then x, a circle event first at one point.
inline Sign event_vs_site(const Event& ev, const Site& s) {
  if (ev.yi.lo > s.yi.hi) return POSITIVE;
  if (ev.yi.hi < s.yi.lo) return NEGATIVE;
  if (const Interval& te = tight(ev); te.lo > s.yi.hi) return POSITIVE;
  else if (te.hi < s.yi.lo) return NEGATIVE;
  const Site &a = *ev.a, &b = *ev.b, &c = *ev.c;
  if (a.exact && b.exact && c.exact && s.exact) return detail::circle_top_vs_site(a.x, a.y, b.x, b.y, c.x, c.y, s.x, s.y);
  const Event::Circle& e = exact(ev);
  const Sign y = root_sign(e.cy - qy(s), Rational(1), e.R);
  if (y != ZERO) return y;
  const Sign x = sign_of(e.cx - qx(s));
  return x != ZERO ? x : NEGATIVE;
}

/// sign(e − f) by y then x: d + √R_e − √R_f with d = cy_e − cy_f.
/// Events of one circle (cocircular sites: a vertex where four or more cells meet) are equal,
/// found by the filtered in_circle before any rational is made.
/// The events found on one circle are kept in classes (union-find on `Event::circle`), so that
/// n events of one circle cost O(n) in_circle tests, not one per comparison.
inline Sign event_vs_event(const std::vector<Event>& evs, int i, int j) {
  const Event &ev = evs[i], &fv = evs[j];
  if (ev.yi.lo > fv.yi.hi) return POSITIVE;
  if (ev.yi.hi < fv.yi.lo) return NEGATIVE;
  if (const int t = translated(ev, fv); t != 2) return static_cast<Sign>(t);
  if (const Interval &te = tight(ev), &tf = tight(fv); te.lo > tf.hi) return POSITIVE;
  else if (te.hi < tf.lo) return NEGATIVE;
  const int ci = circle_of(evs, i), cj = circle_of(evs, j);
  if (ci == cj) return ZERO;
  if (same_circle(ev, fv)) {
    evs[ci].circle = cj;
    return ZERO;
  }
  const Event::Circle &e = exact(ev), &f = exact(fv);
  const Rational d = e.cy - f.cy;
  const Sign u = root_sign(d, Rational(1), e.R);  // d + √R_e, compared with √R_f ≥ 0
  Sign y;
  if (u == NEGATIVE) y = NEGATIVE;
  else if (u == ZERO) y = sgn(f.R) > 0 ? NEGATIVE : ZERO;
  else y = root_sign(d * d + e.R - f.R, Rational(2 * d), e.R);  // (d + √R_e)² − R_f
  return y != ZERO ? y : sign_of(e.cx - f.cx);
}
//< fortune-event-order

}  // namespace t2::detail::fortune_sweep
