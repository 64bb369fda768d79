// The circular sweep of T² (chapter 13; seed 000 §5.8, Algorithm 16), on every kind of segment.
//
// **The sweep.** A half-line of T² turns counter-clockwise around a centre o, from o to ¬o: in
// the spherical model a meridian of the axis through o and ¬o. The centre is on no segment's
// line (circular_centre.cpp), so every line meets every open meridian exactly once, and along a
// segment the angle around o grows strictly, by less than a half turn (its two ends are less
// than a half circle apart). M0, the meridian through r = [0, 1, 0], is the initial position.
// A segment whose inside crosses M0 is cut there into two pieces: the first ends on M0 at the
// end of the turn (angle 2π), the second starts on M0 at its beginning (angle 0). Every other
// segment is one piece. Every piece then spans an interval of [0, 2π], and two pieces cross at
// most once (two lines meet at two antipodal points, half a turn apart, and a piece spans less
// than half a turn): Bentley–Ottmann's setting, with the angle for x and the distance from o
// along the meridian for y. The two pieces of one cut segment are never in the status together
// (the second ends before the first starts, by the same half turn), and they are on one line,
// which `check` skips: no intersection between them is ever reported.
//
// **Event order.** By rank: on M0 at angle 0 (starts), the upper half turn (angle in (0, π),
// orient(o, r, X) > 0), the meridian at π, the lower half turn, M0 at 2π (ends of pieces); in
// a half turn by orient(o, X, Y) (Y after X when positive); on one meridian by the distance
// from o (`along`). Points are input points or meets kept as their four points (join_meet.hpp),
// compared without being constructed.
//
// **Status.** The pieces that cross the meridian of the current event E, ordered from o to ¬o.
// Every piece's line is oriented so that o is on its left (orient(la, lb, o) > 0), so a piece is
// below E (nearer o) when E is on its right. Two pieces through E compare by where the first one
// ends against the second one's line: just after E, as far as its end, a piece stays on one
// side of another's line (the two lines meet again only half a turn further). Collinear pieces
// compare by index. As in sweep.cpp, std::set only compares a key inserted at E, which goes
// through E, against the elements, so only these cases occur.
//
// **Points on M0** are events twice, at 0 and at 2π, each time with part of the segments
// through them (those that start there, those that end there; a cut segment at both): they are
// gathered by their exact point and judged once at the end, with every segment through them.
//
// **A point where many pieces cross** is scheduled once, not once per pair of neighbours (n
// segments through one point made ~2n copies in the heap, and each comparison of two copies is
// a predicate whose filter fails: about 22 s for n = 10⁵), as in sweep.cpp. Each piece remembers
// one crossing waiting in the heap inside it (`Pending`: its number, and another piece through
// it on another line). When neighbours a and b cross ahead and a has a pending crossing w,
// their crossing is w exactly when it lies on the other piece's line (a's line meets that line
// at ±w, and a piece, shorter than half a turn, holds only one of them): one orientation, and
// b learns w. When a and b have the same pending crossing, or one is the other's other piece,
// it is their crossing, with no predicate. The pending crossing of a piece in the status is
// ahead of E or is E (then the piece goes on through E, and forgets it): so a piece whose
// pending crossing has been taken out of the heap passes through E, as do the pieces being
// put back at E (`Piece::through`), both without a predicate. Only the scheduling changes:
// the events, the output and the trace are those of the sweep that pushes every pair.
//
// Traced (the overload with a hook; `t2 animate intersect-circular`), it tells what sweep.cpp
// tells, its pieces named by their segments, and first the centre and the cut segments.
#include <fmt/format.h>

#include <algorithm>
#include <cstdint>
#include <map>
#include <set>
#include <stdexcept>

#include "circular_centre.hpp"
#include "circular_events.hpp"
#include "t2/intersect/intersections.hpp"
#include "t2/kernel/join_meet.hpp"
#include "t2/kernel/lexicographic.hpp"
#include "t2/kernel/orient.hpp"
#include "t2/trace/hook.hpp"

namespace t2 {
namespace circular_sweep {

struct Probe {};  ///< "the current event" for std::set's transparent search

/// A reduced point as a map key.
struct KeyLess {
  bool operator()(const ExactPoint& a, const ExactPoint& b) const {
    const int c0 = cmp(a.w(), b.w()), c1 = cmp(a.x(), b.x());
    return c0 != 0 ? c0 < 0 : c1 != 0 ? c1 < 0 : cmp(a.y(), b.y()) < 0;
  }
};

/// Tells `tr` the reported point ip (`Event::found`).
template <class H>
void tell_found(const IntersectionPoint& ip, H& tr) {
  tell(tr, [&] {
    trace::Report r = trace::about(trace::Event::found, {});
    r.point = &ip.point;
    r.chain = ip.segments;
    return r;
  });
}

class Circular {
 public:
  Circular(const std::vector<Segment>& segments, const Point& centre);
  /// The sweep, telling `tr` (trace/hook.hpp; NoTrace: no trace code) what it does.
  template <class H>
  std::vector<IntersectionPoint> run(H& tr);

 private:
  struct StatusLess {
    using is_transparent = void;
    const Circular* s;
    bool operator()(std::size_t a, std::size_t b) const { return s->below(a, b); }
    bool operator()(std::size_t a, Probe) const { return s->side_of_event(a) == NEGATIVE; }
    bool operator()(Probe, std::size_t b) const { return s->side_of_event(b) == POSITIVE; }
  };
  using Status = std::set<std::size_t, StatusLess>;
  struct Later {
    const Circular* s;
    bool operator()(const Event& a, const Event& b) const { return s->compare(a, b) == POSITIVE; }
  };

  Sign side(const Point& a, const Point& b, const At& x) const;
  Sign orient3(const Point& a, const At& x, const At& y) const;
  Rank rank_of(const At& x, bool end) const;
  Sign along(const At& x, const At& y, const Point& z) const;
  Sign compare(const At& x, Rank rx, const At& y, Rank ry) const;
  Sign compare(const Event& a, const Event& b) const;
  Sign side_of_event(std::size_t k) const;
  bool below(std::size_t a, std::size_t b) const;
  bool collinear(std::size_t s, std::size_t t) const;
  bool lines_differ(const std::vector<std::size_t>& segments) const;
  void add_piece(std::uint32_t segment, const At& start, Rank rs, const At& end, Rank re);
  void make_groups();
  template <class H>
  void check(std::size_t a, std::size_t b, H& tr);
  bool queued(std::size_t a, std::size_t b) const;
  void schedule(Event& e, std::size_t a, std::size_t b);
  template <class H>
  void handle(const Event& e, const Group* g, std::vector<IntersectionPoint>& out, H& tr);
  template <class H>
  void tell_status(const Event& e, const std::vector<std::size_t>& going, H& tr) const;

  Point o_, r_{0, 1, 0}, z_{0, 0, 1};
  Sign z_side_;                          // orient(o, z, r): the side of M0 on the line o ∨ r
  std::vector<std::array<Point, 2>> ends_;  // each segment's ends, la then lb (never moved)
  std::vector<bool> point_;              // the segment is one point
  std::vector<Piece> pieces_;
  std::vector<Group> groups_;
  std::vector<Event> heap_;
  std::vector<std::uint8_t> taken_;      // per crossing id: 1 once taken out of the heap
  Event current_;
  Status status_;
  std::vector<Status::iterator> where_;
  std::vector<std::size_t> ending_, going_, through_;  // reused by handle
  std::map<ExactPoint, std::pair<std::vector<std::size_t>, bool>, KeyLess> on_m0_;
};

Sign Circular::side(const Point& a, const Point& b, const At& x) const {
  return x.p ? orient(a, b, *x.p) : orient(a, b, x.m);
}

/// orient(a, x, y) for points or meets x, y.
Sign Circular::orient3(const Point& a, const At& x, const At& y) const {
  if (x.p && y.p) return x.p == y.p ? ZERO : orient(a, *x.p, *y.p);
  if (x.p) return orient(a, *x.p, y.m);
  if (y.p) return -orient(a, *y.p, x.m);
  return orient(a, x.m, y.m);
}

Rank Circular::rank_of(const At& x, bool end) const {
  const Sign h = side(o_, r_, x);
  if (h != ZERO) return h == POSITIVE ? kUpper : kLower;
  if (side(o_, z_, x) == z_side_) return end ? kEnd : kStart;
  return kHalf;
}

/// x against y on one meridian, nearer o first, with z off that meridian's line: the turn from x
/// to y seen from z has the sign of orient(o, x, z) exactly when y is farther from o.
Sign Circular::along(const At& x, const At& y, const Point& z) const {
  const Sign d = orient3(z, x, y);
  if (d == ZERO) return ZERO;
  return d == side(z, o_, x) ? NEGATIVE : POSITIVE;
}

//> circular-order
/// The order of the sweep: rank, then angle, then distance from o (file comment).
Sign Circular::compare(const At& x, Rank rx, const At& y, Rank ry) const {
  if (rx != ry) return rx < ry ? NEGATIVE : POSITIVE;
  if (rx == kUpper || rx == kLower) {
    // y after x when positive: they are less than a half turn apart
    const Sign turn = orient3(o_, x, y);
    if (turn != ZERO) return -turn;
    return along(x, y, r_);  // r is off every meridian but M0's and π's
  }
  return along(x, y, z_);  // on the line o ∨ r, which z is off
}
//< circular-order

Sign Circular::compare(const Event& a, const Event& b) const {
  if (a.crossing && b.crossing && a.i == b.i && a.j == b.j) return ZERO;
  return compare(a.at, a.rank, b.at, b.rank);
}

//> circular-status
/// Where piece k is against the current event: NEGATIVE below it (nearer o),
/// POSITIVE above, ZERO through it.
Sign Circular::side_of_event(std::size_t k) const {
  const Piece& p = pieces_[k];
  if (p.through || (p.pending.id != kNone && taken_[p.pending.id]))
    return ZERO;  // known through it (file comment)
  if (current_.crossing && (k == current_.i || k == current_.j)) return ZERO;
  // o is on p's left: an event on the left is nearer o than p
  return side(*p.la, *p.lb, current_.at);
}

bool Circular::below(std::size_t a, std::size_t b) const {
  if (a == b) return false;
  const Sign sa = side_of_event(a), sb = side_of_event(b);
  if (sa != ZERO && sb != ZERO)
    throw std::logic_error("circular sweep: compared two pieces off the event");
  if (sa != ZERO) return sa == NEGATIVE;
  if (sb != ZERO) return sb == POSITIVE;
  // Both through the event: a's end, on a's side of b's line all the way from the event.
  const Piece &p = pieces_[a], &q = pieces_[b];
  const Sign s = side(*q.la, *q.lb, p.end);
  return s != ZERO ? s == POSITIVE : a < b;
}
//< circular-status

bool Circular::collinear(std::size_t s, std::size_t t) const {
  const auto &a = ends_[s], &b = ends_[t];
  return orient(a[0], a[1], b[0]) == ZERO && orient(a[0], a[1], b[1]) == ZERO;
}

/// Two of the (segment) indices are on different lines: (b) of intersections.hpp.
bool Circular::lines_differ(const std::vector<std::size_t>& segments) const {
  for (std::size_t k = 1; k < segments.size(); ++k)
    if (!point_[segments[0]] && !point_[segments[k]] && !collinear(segments[0], segments[k])) return true;
  return false;
}

void Circular::add_piece(std::uint32_t segment, const At& start, Rank rs, const At& end, Rank re) {
  const auto& e = ends_[segment];
  pieces_.push_back({&e[0], &e[1], start, end, rs, re, segment});
}

Circular::Circular(const std::vector<Segment>& segments, const Point& centre)
    : o_(centre), status_(StatusLess{this}) {
  if (segments.size() >= (std::size_t{1} << 30)) throw std::length_error("circular sweep: too many segments");
  z_side_ = orient(o_, z_, r_);
  ends_.reserve(segments.size());  // pointers into ends_ are kept: it never grows past this
  point_.resize(segments.size());
  //> circular-cut
  for (std::size_t i = 0; i < segments.size(); ++i) {
    const Segment& s = segments[i];
    const auto k = static_cast<std::uint32_t>(i);
    point_[i] = s.is_degenerate();
    if (point_[i]) {
      ends_.push_back({s.source(), s.source()});
      continue;
    }
    // la first in the turn: o on the left of la ∨ lb (never on it: the centre's
    // rule)
    if (orient(s.source(), s.target(), o_) == POSITIVE)
      ends_.push_back({s.source(), s.target()});
    else
      ends_.push_back({s.target(), s.source()});
    const auto& e = ends_.back();
    const At a{&e[0], {}}, b{&e[1], {}};
    const Rank ra = rank_of(a, false), rb = rank_of(b, true);
    if (ra == kStart || rb == kEnd || compare(a, ra, b, rb) == NEGATIVE) {
      add_piece(k, a, ra, b, rb);  // no wrap past M0
      continue;
    }
    // The cut point w = (la ∨ lb) ∧ (o ∨ r), or its antipode: the one on M0.
    JoinMeet<double> w = join_meet(e[0], e[1], o_, r_);
    if (side(o_, z_, At{nullptr, w}) != z_side_) w = {w.a, w.b, w.d, w.c, Sign(-w.w)};
    add_piece(k, a, ra, At{nullptr, w}, kEnd);    // to M0 at the end of the turn
    add_piece(k, At{nullptr, w}, kStart, b, rb);  // from M0 at its beginning
  }
  //< circular-cut
  where_.resize(pieces_.size());
  make_groups();
}

/// Sorts the endpoint events and gathers equal ones into groups.
void Circular::make_groups() {
  struct Entry {
    Event e;
    std::uint32_t index;
    std::uint8_t kind;  // 0 a piece starts, 1 a piece ends, 2 a one-point segment
  };
  std::vector<Entry> entries;
  entries.reserve(2 * pieces_.size() + point_.size());
  for (std::size_t k = 0; k < pieces_.size(); ++k) {
    const Piece& p = pieces_[k];
    entries.push_back({{p.start, p.start_rank, false, 0, 0}, static_cast<std::uint32_t>(k), 0});
    entries.push_back({{p.end, p.end_rank, false, 0, 0}, static_cast<std::uint32_t>(k), 1});
  }
  for (std::size_t i = 0; i < point_.size(); ++i)
    if (point_[i]) {
      const At a{&ends_[i][0], {}};
      entries.push_back({{a, rank_of(a, false), false, 0, 0}, static_cast<std::uint32_t>(i), 2});
    }
  std::sort(entries.begin(), entries.end(),
            [this](const Entry& a, const Entry& b) { return compare(a.e, b.e) == NEGATIVE; });
  for (std::size_t k = 0; k < entries.size();) {
    Group g;
    g.event = entries[k].e;
    for (; k < entries.size() && compare(entries[k].e, g.event) == ZERO; ++k) {
      const Entry& x = entries[k];
      g.input |= x.e.at.p != nullptr;
      if (x.kind == 0) g.starts.push_back(x.index);
      if (x.kind == 2) g.points.push_back(x.index);
    }
    groups_.push_back(std::move(g));
  }
}

//> circular-check
/// Schedules the crossing of a (below) and b (above), neighbours just after the current
/// event, if they cross before the first of their ends: then they have swapped there.
template <class H>
void Circular::check(std::size_t a, std::size_t b, H& tr) {
  const Piece &p = pieces_[a], &q = pieces_[b];
  const auto told = [&](Sign s) {
    tell(tr, trace::Event::neighbours, {p.segment, q.segment}, {}, s);
  };
  if (collinear(p.segment, q.segment)) return told(ZERO);  // overlaps: found at the ends
  if (queued(a, b)) return told(POSITIVE);  // their crossing waits already (file comment)
  const bool p_first = compare(p.end, p.end_rank, q.end, q.end_rank) != POSITIVE;
  const bool swapped = p_first ? side(*q.la, *q.lb, p.end) == NEGATIVE
                               : side(*p.la, *p.lb, q.end) == POSITIVE;
  if (!swapped) return told(NEGATIVE);
  // The lines meet at ±m; the crossing is the one on p's segment, after la in the turn.
  JoinMeet<double> m = join_meet(*p.la, *p.lb, *q.la, *q.lb);
  Sign s = orient(o_, *p.la, m);
  if (s == ZERO) s = orient(*p.lb, o_, m);  // m = ±la: on the segment if lb is after it
  if (s == NEGATIVE) m = {m.c, m.d, m.a, m.b, Sign(-m.w)};
  Event e{At{nullptr, m}, kStart, true, static_cast<std::uint32_t>(std::min(a, b)),
          static_cast<std::uint32_t>(std::max(a, b))};
  e.rank = rank_of(e.at, false);
  const bool ahead = compare(e, current_) == POSITIVE;
  if (ahead) schedule(e, a, b);  // unless it waits already (file comment)
  told(ahead ? POSITIVE : NEGATIVE);
}
//< circular-check

/// The crossing of neighbours a and b is known to wait in the heap, ahead: the same crossing
/// is pending on both, or one's pending crossing has the other as its other piece.
bool Circular::queued(std::size_t a, std::size_t b) const {
  const Pending pa = pieces_[a].pending, pb = pieces_[b].pending;
  return (pa.id != kNone && (pa.id == pb.id || pa.other == b)) || (pb.id != kNone && pb.other == a);
}

/// Pushes e, the crossing of a and b ahead, unless it lies on the other line of the crossing w
/// pending on one of the two (whose line meets that line at ±w, and a piece holds only one of
/// them): then it is w, and the second learns w.
void Circular::schedule(Event& e, std::size_t a, std::size_t b) {
  const auto ua = static_cast<std::uint32_t>(a), ub = static_cast<std::uint32_t>(b);
  const auto waits = [&](std::uint32_t knows, std::uint32_t learns) {
    const Pending w = pieces_[knows].pending;
    if (w.id == kNone) return false;
    const Piece& t = pieces_[w.other];
    if (orient(*t.la, *t.lb, e.at.m) != ZERO) return false;
    pieces_[learns].pending = {w.id, knows};
    return true;
  };
  if (waits(ua, ub) || waits(ub, ua)) return;
  if (taken_.size() >= kNone) throw std::length_error("circular sweep: too many crossings");
  e.id = static_cast<std::uint32_t>(taken_.size());
  taken_.push_back(0);
  heap_.push_back(e);
  std::push_heap(heap_.begin(), heap_.end(), Later{this});
  pieces_[a].pending = {e.id, ub};
  pieces_[b].pending = {e.id, ua};
}

/// Tells `tr` the status after the event e (its pieces as segments) and the pieces `going` on.
template <class H>
void Circular::tell_status(const Event& e, const std::vector<std::size_t>& going, H& tr) const {
  if constexpr (trace::traced<H>) {
    const ExactPoint at = reduced(e.at.p ? to_exact(*e.at.p) : to_exact(e.at.m));
    std::vector<std::size_t> now, on;
    for (std::size_t k : status_) now.push_back(pieces_[k].segment);
    for (std::size_t k : going) on.push_back(pieces_[k].segment);
    trace::Report r = trace::about(trace::Event::sweep, {}, now);
    r.point = &at;
    r.through = on;
    tr(r);
  }
}

template <class H>
void Circular::handle(const Event& e, const Group* g, std::vector<IntersectionPoint>& out, H& tr) {
  current_ = e;
  // The run of pieces through e: from i's place for a crossing, else found by the probe.
  auto first = status_.end();
  if (g) {
    first = status_.lower_bound(Probe{});
  } else {
    first = where_[e.i];
    while (first != status_.begin() && side_of_event(*std::prev(first)) == ZERO) --first;
  }
  auto& ending = ending_;
  auto& going = going_;
  auto& through = through_;
  ending.clear();
  going.clear();
  through.clear();
  auto above = first;
  for (; above != status_.end() && side_of_event(*above) == ZERO; ++above) {
    const Piece& p = pieces_[*above];
    (g && compare(p.end, p.end_rank, e.at, e.rank) == ZERO ? ending : going).push_back(*above);
  }
  // The segments through e, and the report (on M0: gathered, judged at the end).
  for (std::size_t k : ending) through.push_back(pieces_[k].segment);
  for (std::size_t k : going) through.push_back(pieces_[k].segment);
  if (g) {
    for (std::uint32_t k : g->starts) through.push_back(pieces_[k].segment);
    through.insert(through.end(), g->points.begin(), g->points.end());
  }
  std::sort(through.begin(), through.end());
  through.erase(std::unique(through.begin(), through.end()), through.end());
  const bool input = g && g->input;
  if (e.rank == kStart || e.rank == kEnd) {
    auto& [segs, flag] = on_m0_[reduced(e.at.p ? to_exact(*e.at.p) : to_exact(e.at.m))];
    segs.insert(segs.end(), through.begin(), through.end());
    flag |= input;
  } else if (through.size() >= 2 && (input || lines_differ(through))) {
    out.push_back({reduced(e.at.p ? to_exact(*e.at.p) : to_exact(e.at.m)), through});
    tell_found(out.back(), tr);
  }
  for (std::size_t k : ending) status_.erase(where_[k]);
  for (std::size_t k : going) {  // a crossing pending on it is e
    status_.erase(where_[k]);
    pieces_[k].pending = Pending{};
  }
  // The pieces that go on past e, in their order just after it, each put just below `above`.
  if (g) going.insert(going.end(), g->starts.begin(), g->starts.end());
  for (std::size_t k : going) pieces_[k].through = true;  // every key compared below
  std::sort(going.begin(), going.end(), [this](std::size_t a, std::size_t b) { return below(a, b); });
  for (std::size_t k : going) where_[k] = status_.insert(above, k);
  for (std::size_t k : going) pieces_[k].through = false;
  tell_status(e, going, tr);
  if (going.empty()) {
    if (above != status_.begin() && above != status_.end()) check(*std::prev(above), *above, tr);
    return;
  }
  const auto lo = where_[going.front()], hi = where_[going.back()];
  if (lo != status_.begin()) check(*std::prev(lo), *lo, tr);
  if (std::next(hi) != status_.end()) check(*hi, *std::next(hi), tr);
}

template <class H>
std::vector<IntersectionPoint> Circular::run(H& tr) {
  std::vector<IntersectionPoint> out;
  if constexpr (trace::traced<H>) {  // the centre, and the segments cut in two pieces
    const ExactPoint o = reduced(to_exact(o_));
    std::vector<std::size_t> cut;
    for (std::size_t k = 1; k < pieces_.size(); ++k)
      if (pieces_[k].segment == pieces_[k - 1].segment) cut.push_back(pieces_[k].segment);
    trace::Report r = trace::about(trace::Event::sweep_start, {}, cut);
    r.point = &o;
    tr(r);
  }
  //> circular-loop
  std::size_t g = 0;
  while (g < groups_.size() || !heap_.empty()) {
    const bool endpoint =
        g < groups_.size() &&
        (heap_.empty() || compare(groups_[g].event, heap_.front()) != POSITIVE);
    const Event e = endpoint ? groups_[g].event : heap_.front();
    while (!heap_.empty() && compare(heap_.front(), e) == ZERO) {  // every copy of e
      taken_[heap_.front().id] = 1;
      std::pop_heap(heap_.begin(), heap_.end(), Later{this});
      heap_.pop_back();
    }
    handle(e, endpoint ? &groups_[g++] : nullptr, out, tr);
  }
  //< circular-loop
  for (auto& [point, entry] : on_m0_) {
    auto& [segs, input] = entry;
    std::sort(segs.begin(), segs.end());
    segs.erase(std::unique(segs.begin(), segs.end()), segs.end());
    if (segs.size() >= 2 && (input || lines_differ(segs))) {
      out.push_back({point, segs});
      tell_found(out.back(), tr);
    }
  }
  std::sort(out.begin(), out.end(),
            [](const IntersectionPoint& a, const IntersectionPoint& b) { return less_wxy(a.point, b.point); });
  return out;
}

}  // namespace circular_sweep

std::vector<IntersectionPoint> intersections_circular(const std::vector<Segment>& segments) {
  NoTrace none;
  return circular_sweep::Circular(segments, detail::circular_centre(segments)).run(none);
}

std::vector<IntersectionPoint> intersections_circular(const std::vector<Segment>& segments,
                                                      const trace::AnyHook& hook) {
  return circular_sweep::Circular(segments, detail::circular_centre(segments)).run(hook);
}

}  // namespace t2
