// Fortune's sweep (t2/voronoi/fortune.hpp): the breakpoint predicate, the sweep, and the
// contraction of zero-length edges at cocircular sites (the events and their order:
// fortune_events.hpp).
#include "t2/voronoi/fortune.hpp"

#include <algorithm>
#include <cmath>
#include <memory>
#include <numeric>
#include <queue>
#include <string>

#include "fortune_beach.hpp"
#include "fortune_events.hpp"
#include "fortune_exact.hpp"
#include "fortune_interval.hpp"
#include "t2/kernel/error.hpp"
#include "t2/kernel/incircle.hpp"
#include "t2/kernel/number.hpp"
#include "t2/kernel/orient.hpp"
#include "t2/kernel/sign_sqrt.hpp"
#include "t2/trace/hook.hpp"

namespace t2 {

namespace {

using Index = FortuneDiagram::Index;
using detail::Arc;
using detail::Interval;
using namespace detail::fortune_sweep;


//> fortune-breakpoint
/// sign(β − a), β the abscissa of the breakpoint of the arcs of p (left) and q (right)
/// when the sweep line is y = L, for the site s = (a, L) (file comment of fortune.hpp).
/// The same formula in intervals decides first when it can.
Sign breakpoint_side(const Site& p, const Site& q, const Site& s) {
  {
    const Interval dp = p.yi - s.yi, dq = q.yi - s.yi, den = dq - dp;
    if (const int sd = den.sign(); sd != 2) {
      const Interval dx = p.xi - q.xi, dy = p.yi - q.yi;
      const Interval C = dp * dq * (dx * dx + dy * dy);
      const Interval r = dq * p.xi - dp * q.xi - s.xi * den - sqrt(C);
      if (const int sr = r.sign(); sr != 2) return static_cast<Sign>(sd * sr);
    }
  }
  if (p.exact && q.exact && s.exact)  // w = 1: the same signs on the doubles, exact
    return detail::breakpoint_sign(p.x, p.y, q.x, q.y, s.x, s.y);
  const Rational L = qy(s), a = qx(s), px = qx(p), py = qy(p);
  const Rational qx_ = qx(q), qy_ = qy(q);
  const Rational dp = py - L, dq = qy_ - L;
  if (dp == dq) return sign_of(Rational(px + qx_) / 2 - a);
  const Rational dx = px - qx_, dy = py - qy_;
  const Rational A = dq * px - dp * qx_ - a * (dq - dp);
  const Rational C = dp * dq * (dx * dx + dy * dy);
  return sign_of(dq - dp) * root_sign(A, Rational(-1), C);
}
//< fortune-breakpoint


/// An edge of the sweep: its two sites and its two ends (vertex numbers, -1 while open).
struct SweepEdge {
  Index s, t;
  int end[2] = {-1, -1};
};

/// A vertex of the sweep: its centre and its three sites (counter-clockwise).
struct SweepVertex {
  Index a, b, c;
  int event;  // the circle event that made it
};

/// The sweep's state; `hook` hears its events (trace/hook.hpp: site, circle, schedule,
/// false_alarm, breakpoint), in input indices, with the beach line as the report's chain. For
/// `NoTrace` no report is built: the untraced sweep has no trace code.
template <class H>
class Sweep {
 public:
  Sweep(const std::vector<Site>& sites, H& hook) : s_(sites), hook_(hook) { ev_.reserve(3 * sites.size()); }

  //> fortune-sweep
  void run() {
    std::size_t i = 1;
    beach_.start(make(0));
    Arc* last = head_ = beach_.root;  // the leftmost arc: never removed (no left neighbour)
    report(trace::Event::site, {s_[0].id});
    for (; i < s_.size() && compare_sites(s_[i], s_[0], false) == 0; ++i) {  // the first row: vertical rays
      Arc* n = make(int(i));
      beach_.insert_after(last, n);
      n->edge = new_edge(last->site, n->site), n->end = 1;
      last = n;
      report(trace::Event::site, {s_[i].id});
    }
    while (i < s_.size() || !queue_.empty()) {
      if (!queue_.empty() && (i == s_.size() || event_vs_site(ev_[queue_.top().id], s_[i]) < 0)) {
        const int e = queue_.top().id;
        queue_.pop();
        if (ev_[e].valid) remove(e);
      } else {
        insert(int(i++));
      }
    }
  }
  //< fortune-sweep

  std::vector<SweepEdge> edges;
  std::vector<SweepVertex> vertices;
  /// True when the events of vertices v and w have disjoint enclosures of y (two circles).
  bool apart(int v, int w) const {
    const Interval &a = ev_[vertices[v].event].yi, &b = ev_[vertices[w].event].yi;
    return a.hi < b.lo || b.hi < a.lo;
  }
  /// True when the sweep found vertices v and w on one circle (then they are one point).
  bool known_cocircular(int v, int w) const {
    return circle_of(ev_, vertices[v].event) == circle_of(ev_, vertices[w].event);
  }

 private:
  int new_edge(int p, int q) {
    edges.push_back({s_[p].id, s_[q].id});
    return int(edges.size()) - 1;
  }
  /// Tells the hook event e about the sites `at` (input indices), with the beach line.
  void report(trace::Event e, std::initializer_list<std::size_t> at, Sign sign = ZERO) {
    if constexpr (trace::traced<H>) {
      ids_.clear();
      for (const Arc* a = head_; a; a = a->next) ids_.push_back(s_[a->site].id);
      tell(hook_, e, at, ids_, sign);
    }
  }
  /// sign(β − a) of breakpoint_side, told to the hook.
  Sign side(const Arc* l, const Arc* r, const Site& s) {
    const Sign g = breakpoint_side(s_[l->site], s_[r->site], s);
    if constexpr (trace::traced<H>) report(trace::Event::breakpoint, {s_[l->site].id, s_[r->site].id, s.id}, g);
    return g;
  }
  /// The breakpoint of the arcs of l and r on the sweep line y = L, in rounded doubles (a guess:
  /// the formula of breakpoint_side, or NaN).
  double guess(const Arc* l, const Arc* r, double L) const {
    const Site &p = s_[l->site], &q = s_[r->site];
    if (p.y == q.y) return 0.5 * (p.x + q.x);
    const double dp = p.y - L, dq = q.y - L, dx = p.x - q.x, dy = p.y - q.y;
    return (dq * p.x - dp * q.x - std::sqrt(dp * dq * (dx * dx + dy * dy))) / (dq - dp);
  }
  /// A new arc of site i.
  Arc* make(int i) { return beach_.make(i); }
  /// The arc above the abscissa of site s (the right one on a breakpoint).
  /// Untraced, a search in rounded doubles guesses the arc, and two exact comparisons (its two
  /// breakpoints) certify it: the arc with s.x in (left breakpoint, right breakpoint] is unique,
  /// so a certified guess is the answer; a wrong guess (ties, rounding) goes the exact way.
  Arc* locate(const Site& s) {
    if constexpr (!trace::traced<H>) {
      Arc* n = beach_.root;
      for (;;) {
        if (n->prev && s.x < guess(n->prev, n, s.y)) n = n->left;
        else if (n->next && !(s.x < guess(n, n->next, s.y))) n = n->right;
        else break;
      }
      if ((!n->prev || side(n->prev, n, s) <= 0) && (!n->next || side(n, n->next, s) > 0)) return n;
    }
    Arc* n = beach_.root;
    for (;;) {
      if (n->prev && side(n->prev, n, s) > 0) n = n->left;
      else if (n->next && side(n, n->next, s) <= 0) n = n->right;
      else return n;
    }
  }
  void drop_event(Arc* a) {
    if (a->event < 0) return;
    Event& e = ev_[a->event];
    e.valid = false, a->event = -1;
    if constexpr (trace::traced<H>) report(trace::Event::false_alarm, {e.a->id, e.b->id, e.c->id});
  }
  /// A site event: the arc above splits into two around the new arc.
  void insert(int site) {
    Arc* a = locate(s_[site]);
    Arc* n = make(site);
    Arc* b = make(a->site);
    beach_.insert_after(a, n);
    beach_.insert_after(n, b);
    const int e = new_edge(a->site, site);
    n->edge = e, n->end = 0;
    b->edge = e, b->end = 1;
    report(trace::Event::site, {s_[site].id, s_[a->site].id});
    drop_event(a);  // after the split: the arcs' events are kept on the arcs, untouched by it
    check(a);
    check(b);
  }
  /// A circle event: its arc goes, a vertex and an edge start.
  void remove(int e) {
    Arc* m = ev_[e].arc;
    Arc* l = m->prev;
    Arc* r = m->next;
    const int v = int(vertices.size());
    vertices.push_back({s_[l->site].id, s_[m->site].id, s_[r->site].id, e});
    edges[m->edge].end[m->end] = v;
    edges[r->edge].end[r->end] = v;
    const int g = new_edge(l->site, r->site);
    edges[g].end[0] = v;
    r->edge = g, r->end = 1;
    m->event = -1;
    beach_.erase(m);
    report(trace::Event::circle, {s_[l->site].id, s_[m->site].id, s_[r->site].id});
    drop_event(l);
    drop_event(r);
    check(l);
    check(r);
  }
  /// A circle event for the arc m when its neighbours' sites turn counter-clockwise.
  void check(Arc* m) {
    Arc* l = m->prev;
    Arc* r = m->next;
    if (!l || !r || l->site == r->site) return;
    const Site &a = s_[l->site], &b = s_[m->site], &c = s_[r->site];
    if (orient(a.p, b.p, c.p) != POSITIVE) return;
    ev_.push_back(Event{&a, &b, &c, event_y(a, b, c), m, true, false, int(ev_.size())});
    m->event = int(ev_.size()) - 1;
    queue_.push({ev_.back().yi.lo, ev_.back().yi.hi, m->event});
    report(trace::Event::schedule, {a.id, b.id, c.id});
  }
  /// An event in the queue: the enclosure of its y beside its number, so that most
  /// comparisons read neither the event nor its sites.
  struct Queued {
    double lo, hi;
    int id;
  };
  struct Later {
    const std::vector<Event>* ev;
    bool operator()(const Queued& a, const Queued& b) const {
      if (a.lo > b.hi) return true;
      if (a.hi < b.lo) return false;
      const Sign s = event_vs_event(*ev, a.id, b.id);
      return s != ZERO ? s > 0 : a.id > b.id;
    }
  };
  const std::vector<Site>& s_;
  H& hook_;
  Arc* head_ = nullptr;
  std::vector<std::size_t> ids_;  // the beach line in input indices, when traced
  detail::BeachLine beach_;
  std::vector<Event> ev_;
  std::priority_queue<Queued, std::vector<Queued>, Later> queue_{Later{&ev_}};
};

/// The pole [0, ℓ_x, ℓ_y] of ℓ = p ∨ q: the point of Ω to the left of p → q.
ExactPoint left_pole(const Point& a, const Point& b) {
  const ExactPoint p = to_exact(a), q = to_exact(b);
  return ExactPoint(Integer(0), Integer(p.y() * q.w() - p.w() * q.y()), Integer(p.w() * q.x() - p.x() * q.w()));
}

int find(std::vector<int>& up, int v) {
  while (up[v] != v) v = up[v] = up[up[v]];
  return v;
}

}  // namespace

namespace {

/// Fortune's sweep telling `hook` (NoTrace: nothing).
template <class H>
FortuneDiagram sweep_sites(std::span<const Point> points, H& hook) {
  FortuneDiagram out;
  out.sites.assign(points.begin(), points.end());
  std::vector<Site> s;
  s.reserve(points.size());
  for (std::size_t i = 0; i < points.size(); ++i) {
    const Point& p = points[i];
    if (!(p.w() > 0))
      throw Undefined("fortune: site " + std::to_string(i) + " " + to_string(p) +
                      " is not on the front side (Fortune's sweep works in the plane of the front side)");
    const bool one = p.w() == 1;  // then x/w and y/w are the doubles x and y
    const double x = one ? p.x() : p.x() / p.w(), y = one ? p.y() : p.y() / p.w();
    s.push_back({x, y, one ? Interval{x, x} : Interval::around(x).settled(), one ? Interval{y, y} : Interval::around(y).settled(), p,
                 Index(i), one});
  }
  // The sweep order (y, then x, then the input order): on keys of 24 bytes when every site has
  // w = 1, else on the sites by compare_sites.
  std::vector<Index> order(s.size());
  if (std::all_of(s.begin(), s.end(), [](const Site& x) { return x.exact; })) {
    struct Key {
      double y, x;
      Index i;
    };
    std::vector<Key> k(s.size());
    for (std::size_t i = 0; i < s.size(); ++i) k[i] = {s[i].y, s[i].x, Index(i)};
    std::sort(k.begin(), k.end(), [](const Key& a, const Key& b) {
      return a.y != b.y ? a.y < b.y : a.x != b.x ? a.x < b.x : a.i < b.i;
    });
    for (std::size_t i = 0; i < s.size(); ++i) order[i] = k[i].i;
  } else {
    std::iota(order.begin(), order.end(), Index(0));
    std::stable_sort(order.begin(), order.end(), [&](Index a, Index b) { return compare_sites(s[a], s[b], true) < 0; });
  }
  std::vector<Site> u;  // distinct sites, the first of each group kept
  u.reserve(s.size());
  for (Index i : order) {
    const Site& x = s[i];
    if (!u.empty() && compare_sites(u.back(), x, true) == 0) out.duplicates.push_back({x.id, u.back().id});
    else u.push_back(x);
  }
  std::vector<Site>().swap(s);
  std::sort(out.duplicates.begin(), out.duplicates.end());
  out.first.push_back(0);
  if (u.size() < 2) return out;
  Sweep<H> sweep(u, hook);
  sweep.run();
  // Contract the zero-length edges (cocircular sites): vertices at one centre become one.
  // Both ends of an edge between s and t are circles through s and t (the edge's breakpoint
  // runs between their arcs), so they are one point exactly when the third site of one end is
  // on the circle of the other: in_circle = 0 (exact, filtered).
  const auto& V = sweep.vertices;
  auto third = [](const SweepVertex& v, const SweepEdge& e) {
    return v.a != e.s && v.a != e.t ? v.a : v.b != e.s && v.b != e.t ? v.b : v.c;
  };
  std::vector<int> up(V.size());
  std::iota(up.begin(), up.end(), 0);
  // Two circles through s and t with one centre are one circle, with one event: ends whose
  // events' enclosures are apart are two points, without in_circle.
  for (const SweepEdge& e : sweep.edges)
    if (e.end[0] >= 0 && e.end[1] >= 0 && !sweep.apart(e.end[0], e.end[1]) &&
        (sweep.known_cocircular(e.end[0], e.end[1]) ||
         in_circle(points[e.s], points[e.t], points[third(V[e.end[0]], e)], points[third(V[e.end[1]], e)]) == ZERO))
      up[find(up, e.end[0])] = find(up, e.end[1]);
  std::vector<int> number(V.size(), -1);
  std::vector<Index> start{0};  // the sites of the sweep vertices of vertex k: around[start[k] ..)
  for (std::size_t v = 0; v < V.size(); ++v) {
    const int r = find(up, int(v));
    if (number[r] < 0) {
      number[r] = int(out.circles.size());
      out.circles.push_back({V[r].a, V[r].b, V[r].c});
      start.push_back(0);
    }
    number[v] = number[r];
    start[number[v] + 1] += 3;
  }
  for (std::size_t k = 1; k < start.size(); ++k) start[k] += start[k - 1];
  std::vector<Index> around(start.back()), fill(start.begin(), start.end() - 1);
  for (std::size_t v = 0; v < V.size(); ++v)
    for (Index x : {V[v].a, V[v].b, V[v].c}) around[fill[number[v]]++] = x;
  //> fortune-around
  // The sites of each vertex, counter-clockwise around its centre (exact).
  std::vector<Index> rank(points.size());  // a site's place in the sweep order
  for (std::size_t k = 0; k < u.size(); ++k) rank[u[k].id] = Index(k);
  out.cells.reserve(around.size());
  std::vector<Index> a;
  for (std::size_t k = 0; k + 1 < start.size(); ++k) {
    if (start[k + 1] - start[k] == 3) {  // one circle event: l, m, r turn counter-clockwise (orient > 0)
      out.cells.insert(out.cells.end(), around.begin() + start[k], around.begin() + start[k + 1]);
      out.first.push_back(Index(out.cells.size()));
      continue;
    }
    a.assign(around.begin() + start[k], around.begin() + start[k + 1]);
    // Four or more sites on one circle, whose centre is the vertex: counter-clockwise around
    // the centre is counter-clockwise along the circle, the order of a convex polygon. From its
    // lowest site o (the first in sweep order), every other site is in the half-plane above
    // o's row or to its right on it, and no two are collinear with o (three points of a
    // circle never are), so orient(o, p, q) > 0 orders them (exact, filtered; no centre made).
    std::sort(a.begin(), a.end());
    a.erase(std::unique(a.begin(), a.end()), a.end());
    std::iter_swap(a.begin(), std::min_element(a.begin(), a.end(), [&](Index x, Index y) { return rank[x] < rank[y]; }));
    const Point& o = points[a[0]];
    std::sort(a.begin() + 1, a.end(), [&](Index p, Index q) { return orient(o, points[p], points[q]) == POSITIVE; });
    out.cells.insert(out.cells.end(), a.begin(), a.end());
    out.first.push_back(Index(out.cells.size()));
  }
  //< fortune-around
  for (const SweepEdge& e : sweep.edges) {
    const int a = e.end[0] >= 0 ? number[e.end[0]] : -1, b = e.end[1] >= 0 ? number[e.end[1]] : -1;
    if (a >= 0 && b >= 0) {
      if (a != b) out.edges.push_back({Index(a), Index(b), e.s, e.t});
    } else if (a < 0 && b < 0) {
      out.lines.push_back({e.s, e.t});
    } else {
      const int v = std::max(a, b);
      // A third site of the vertex: the ray leaves it behind (s t is a hull edge, so every
      // other site of the vertex is on one side of it; the first found, not a scan of them all:
      // n cocircular sites have n rays at one vertex).
      Index w = e.s;
      for (Index x : out.vertex_sites(Index(v)))
        if (x != e.s && x != e.t) {
          w = x;
          break;
        }
      const bool left = orient(points[e.s], points[e.t], points[w]) == POSITIVE;
      out.rays.push_back({Index(v), left ? left_pole(points[e.t], points[e.s]) : left_pole(points[e.s], points[e.t]), e.s, e.t});
    }
  }
  return out;
}

}  // namespace

FortuneDiagram fortune(std::span<const Point> points) {
  NoTrace none;
  return sweep_sites(points, none);
}

FortuneDiagram fortune(std::span<const Point> points, const trace::AnyHook& hook) {
  return sweep_sites(points, hook);
}

}  // namespace t2
