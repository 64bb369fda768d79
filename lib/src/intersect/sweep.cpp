// Bentley–Ottmann on front segments (chapter 13), with exact events and an exact status order.
//
// Events are the points of the queue, in the xy order of lexicographic.hpp: the input endpoints
// and the crossings of two segments' lines, each kept as its four input points (join_meet.hpp):
// compared without being constructed. Every predicate is a filtered polynomial in the input
// doubles (orient.hpp, lexicographic.hpp, join_meet.hpp), exact for every finite double; the
// exact integer point is constructed only for a reported point. The endpoints are sorted once
// and grouped (equal points are one event); the crossings wait in a binary heap, where the same
// point may wait several times (rarely, see below): every copy is taken out with the first, and
// an endpoint event takes the crossings equal to it. The status is a std::set of segment indices
// ordered at the current event E. Its invariant, between two events, is: the segments of the
// status are the segments that meet the sweep line x = E.x at or after E (ordered
// lexicographically, a vertical segment is met where its points lie), sorted bottom to top by
// where they meet it; segments through one point of that line are sorted by their order just
// right of it (by slope), a vertical one last, and collinear ones by index. The invariant holds
// because every point where two segments swap is an event (the classic lemma: two segments are
// adjacent in the status just before their leftmost common point), and at each event every
// segment through it is taken out and put back.
//
// The comparator therefore only ever has to order a segment through E against another one: a
// segment not through E is below or above E (the orientation of E with the segment's ends; no
// predicate for a segment known to pass through E, next paragraph), two segments through E
// compare by the sign of w of the meet of their lines (join_meet.hpp's `turn`: of the two
// common points of the lines, the one for which they turn counter-clockwise — front, i.e. the
// first line is below the second right of E, exactly when w > 0). std::set only compares the
// key being inserted with the elements, and every key inserted at E goes through E; elements
// are erased by iterator.
//
// A point where many segments cross is scheduled once, not once per pair of neighbours (n
// segments through one point made ~2n copies, and each heap comparison of two copies is a
// predicate whose filter must fail, ending in an exact stage: 38 s for n = 10⁵). Each segment
// remembers one crossing waiting in the heap on it (`Pending`: its heap id, and another segment
// through it on another line). When neighbours a and b meet ahead of E and a has a pending
// crossing q, their meet is q exactly when it lies on q's other line (a's line meets that line
// in one front point): one orientation of degree 6 (an exact stage once per segment through q,
// not a comparison of two meets of degree 8 per heap step), and b learns q. When a and b have
// the same pending crossing, or q's other segment is b, their meet is q, with no predicate at
// all. And when the crossing a knew before q (`before_`) was b's, a third segment came between
// them since; ahead of E, that crossing still waits (polygon-edges, n = 10⁵: 3.65M pushes for
// 2.63M points, now 2.72M). The pending crossing of a segment in the status is ahead of E, or
// is E: the segment passes through it, so at that event it is in the run through E (handle)
// and forgets it, or ends there and leaves the status. So a segment of the status whose
// pending crossing has been taken out of the heap passes through E, as do the segments
// being put back at E (`Piece::through`): both are known without a predicate. Scheduling is the
// only change: the points in the heap, hence the events, the output and the trace, are those
// of the sweep that pushes every pair.
//
// Traced (the overload with a hook; `t2 animate intersect`), the sweep tells each reported point,
// the status after each event and each test of two neighbours (trace/hook.hpp), in segment
// indices; the untraced run is the NoTrace instantiation, without trace code.
#include <fmt/format.h>

#include <algorithm>
#include <cstdint>
#include <set>
#include <stdexcept>

#include "t2/intersect/intersections.hpp"
#include "t2/kernel/join_meet.hpp"
#include "t2/kernel/lexicographic.hpp"
#include "t2/kernel/orient.hpp"
#include "t2/trace/hook.hpp"

namespace t2 {
// Named: a unity build (test.sh) shares one translation unit between this file and the
// other sweeps, whose helpers have the same names.
namespace plane_sweep {

/// What segment i knows of a crossing waiting in the heap that lies on it: its `id`, and
/// `other`, a segment through that crossing on another line than i's.
struct Pending {
  std::uint32_t id = std::uint32_t(-1), other = std::uint32_t(-1);  ///< none: both -1
};

/// A front segment from its lower-left end to its upper-right end (the xy order), in doubles,
/// with what the sweep knows of it: 64 bytes, one cache line for each status comparison.
struct Piece {
  Point left{1, 0, 0}, right{1, 0, 0};
  Pending pending;        ///< a crossing ahead on it (file comment), or none
  bool vertical = false;  ///< left and right have the same x
  bool point = false;     ///< zero length: never in the status
  bool through = false;   ///< put back at the current event: it passes through it
};
static_assert(sizeof(Piece) <= 64);

/// An event: an endpoint p of segment i (a point of `pieces_`) or the crossing m of segments
/// i < j.
struct Event {
  const Point* p = nullptr;  ///< the endpoint, or null for a crossing
  JoinMeet<double> m{};      ///< the crossing (front: m.w is POSITIVE)
  std::uint32_t i = 0, j = 0;
  std::uint32_t id = 0;      ///< a crossing: its number in the heap, one for each push
};

/// Endpoint events with equal points are one group: its point and the segments starting there.
struct Group {
  const Point* p;
  std::uint32_t segment;     ///< p is an end of this segment
  std::uint32_t begin, end;  ///< the range of `starts_`
};

/// The lookup key for "where the current event is" in the status (std::set's transparent search).
struct Probe {};

class Sweep {
 public:
  explicit Sweep(const std::vector<Segment>& segments);
  /// The sweep, telling `tr` (trace/hook.hpp; NoTrace: no trace code) what it does.
  template <class H>
  std::vector<IntersectionPoint> run(H& tr);

 private:
  struct StatusLess {
    using is_transparent = void;
    const Sweep* s;
    bool operator()(std::size_t a, std::size_t b) const { return s->below(a, b); }
    bool operator()(std::size_t a, Probe) const { return s->side_of_event(a) == POSITIVE; }
    bool operator()(Probe, std::size_t b) const { return s->side_of_event(b) == NEGATIVE; }
  };
  using Status = std::set<std::size_t, StatusLess>;
  /// The heap order: the least event on top.
  struct Later {
    const Sweep* s;
    bool operator()(const Event& a, const Event& b) const { return s->compare_events(a, b) == POSITIVE; }
  };

  Sign compare_events(const Event& a, const Event& b) const;
  bool on_vertical(const Event& a, const Event& b) const;
  Sign side_of_event(std::size_t i) const;
  bool below(std::size_t a, std::size_t b) const;
  template <class H>
  void handle(const Event& e, const std::uint32_t* upper_begin, const std::uint32_t* upper_end,
              std::vector<IntersectionPoint>& out, H& tr);
  template <class H>
  void check(std::size_t a, std::size_t b, H& tr);
  /// Segment s now knows q pending on it (the one it knew goes to before_).
  void learn(std::uint32_t s, Pending q) {
    Pending& p = pieces_[s].pending;
    if (p.id != kNoSlot && p.id != q.id) before_[s] = p;
    p = q;
  }

  std::vector<Piece> pieces_;
  std::vector<Group> groups_;          // the endpoint events, sorted
  std::vector<std::uint32_t> starts_;  // the segments starting at each group
  std::vector<Event> heap_;            // the crossings still ahead (std::push_heap, Later)
  Event current_;
  Status status_;
  std::vector<Status::iterator> where_;
  std::vector<std::size_t> lower_, inner_;  // reused by handle
  std::vector<Status::node_type> moved_;    // the nodes of inner_, out of the status
  std::vector<std::uint32_t> slot_;         // segment i's node is moved_[slot_[i]] (else kNoSlot)
  static constexpr std::uint32_t kNoSlot = std::uint32_t(-1);
  std::vector<std::size_t> order_;          // the segments put back at the event
  std::vector<Pending> before_;             // per segment: the one pending before (in the heap if ahead)
  std::vector<std::uint8_t> taken_;         // per heap id: 1 once taken out of the heap
};

Sweep::Sweep(const std::vector<Segment>& segments)
    : status_(StatusLess{this}), where_(segments.size()), slot_(segments.size(), kNoSlot),
      before_(segments.size()) {
  if (segments.size() >= (std::size_t{1} << 31)) throw std::length_error("sweep: too many segments");
  pieces_.resize(segments.size());
  struct End {
    const Point* p;
    std::uint32_t segment;
    bool starts;
  };
  std::vector<End> ends;
  ends.reserve(2 * segments.size());
  for (std::size_t i = 0; i < segments.size(); ++i) {
    const Segment& s = segments[i];
    if (!(s.source().w() > 0 && s.target().w() > 0))
      throw Undefined(fmt::format(
          "segment {} ({}): the sweep takes front segments only (both endpoints with w > 0); the brute force "
          "takes every segment of T2",
          i, to_string(s)));
    Piece& p = pieces_[i];
    p.left = s.source();
    p.right = s.target();
    const Sign c = compare_xy(p.left, p.right);
    if (c == POSITIVE) std::swap(p.left, p.right);
    p.point = c == ZERO;
    p.vertical = !p.point && compare_x(p.left, p.right) == ZERO;
    ends.push_back({&p.left, static_cast<std::uint32_t>(i), true});
    if (!p.point) ends.push_back({&p.right, static_cast<std::uint32_t>(i), false});
  }
  std::sort(ends.begin(), ends.end(), [](const End& a, const End& b) { return compare_xy(*a.p, *b.p) == NEGATIVE; });
  starts_.reserve(segments.size());
  for (std::size_t k = 0; k < ends.size();) {
    Group g{ends[k].p, ends[k].segment, static_cast<std::uint32_t>(starts_.size()), 0};
    for (; k < ends.size() && compare_xy(*ends[k].p, *g.p) == ZERO; ++k)
      if (ends[k].starts) starts_.push_back(ends[k].segment);
    g.end = static_cast<std::uint32_t>(starts_.size());
    groups_.push_back(g);
  }
}

/// True when a and b lie on one vertical segment that both name (an end of it, or a crossing of
/// it): then their x are equal, known without a predicate (which could only end in an exact stage).
bool Sweep::on_vertical(const Event& a, const Event& b) const {
  const auto on = [&](std::uint32_t s, const Event& e) { return e.i == s || (!e.p && e.j == s); };
  return (pieces_[a.i].vertical && on(a.i, b)) || (!a.p && pieces_[a.j].vertical && on(a.j, b));
}

/// compare_xy of two events of either form; two copies of one crossing are equal at once.
Sign Sweep::compare_events(const Event& a, const Event& b) const {
  if (a.p && b.p) return compare_xy(*a.p, *b.p);
  if (!a.p && !b.p && a.i == b.i && a.j == b.j) return ZERO;
  if (on_vertical(a, b)) {
    if (a.p) return -compare_y(b.m, *a.p);
    return b.p ? compare_y(a.m, *b.p) : compare_y(a.m, b.m);
  }
  if (a.p) return compare_xy(*a.p, b.m);
  if (b.p) return compare_xy(a.m, *b.p);
  return compare_xy(a.m, b.m);
}

/// The side of the current event on segment i's line (positive: the segment is below it). A
/// vertical segment in the status always holds the event (it is there from its lower end to its
/// upper end, and every event in between lies on it): ZERO. So do the ends of i and the
/// crossings of i, known without a predicate.
Sign Sweep::side_of_event(std::size_t i) const {
  const Piece& p = pieces_[i];
  if (p.through || p.vertical) return ZERO;
  if (p.pending.id != kNoSlot && taken_[p.pending.id]) return ZERO;
  if (current_.p) {
    if (current_.p == &p.left || current_.p == &p.right) return ZERO;
    return orient(p.left, p.right, *current_.p);
  }
  if (i == current_.i || i == current_.j) return ZERO;
  return orient(p.left, p.right, current_.m);
}

bool Sweep::below(std::size_t a, std::size_t b) const {
  if (a == b) return false;
  const Sign sa = side_of_event(a), sb = side_of_event(b);
  if (sa != ZERO && sb != ZERO) throw std::logic_error("sweep: the status compared two segments off the event");
  if (sa != ZERO) return sa == POSITIVE;  // a below the event, b through it
  if (sb != ZERO) return sb == NEGATIVE;  // b above the event, a through it
  const Piece &p = pieces_[a], &q = pieces_[b];
  if (p.vertical || q.vertical) return p.vertical == q.vertical ? a < b : q.vertical;
  const Sign w = turn(p.left, p.right, q.left, q.right);
  return w != ZERO ? w == POSITIVE : a < b;
}

/// Schedules the crossing of a and b (neighbours in the status, a below) if it comes after the
/// event, and tells `tr` the test's answer.
template <class H>
void Sweep::check(std::size_t a, std::size_t b, H& tr) {
  const auto told = [&](Sign s) { tell(tr, trace::Event::neighbours, {a, b}, {}, s); };
  const Sign w = turn(pieces_[a].left, pieces_[a].right, pieces_[b].left, pieces_[b].right);
  if (w == ZERO) return told(ZERO);  // parallel or collinear: overlaps are found at their endpoints
  const Pending pa = pieces_[a].pending, pb = pieces_[b].pending;
  // Waiting: their lines meet there only.
  if ((pa.id != kNoSlot && (pa.id == pb.id || pa.other == b)) || (pb.id != kNoSlot && pb.other == a))
    return told(POSITIVE);
  {  // segment.hpp's `intersects` without its degenerate cases: neither is a point (points never
     // enter the status) and their lines differ (w ≠ 0)
    const Point &pa = pieces_[a].left, &pb = pieces_[a].right, &qa = pieces_[b].left, &qb = pieces_[b].right;
    const int s1 = orient(pa, pb, qa), s2 = orient(pa, pb, qb), s3 = orient(qa, qb, pa), s4 = orient(qa, qb, pb);
    if (!((s3 >= 0 && s4 <= 0 && s1 <= 0 && s2 >= 0) || (s3 <= 0 && s4 >= 0 && s1 >= 0 && s2 <= 0)))
      return told(NEGATIVE);
  }
  const std::size_t under = a, over = b;  // as tested, before the swap below
  if (w == NEGATIVE) std::swap(a, b);  // the front one of the two meets: turn(a, b) > 0
  const Piece &p = pieces_[a], &q = pieces_[b];
  Event e;
  // join_meet would compute this turn again: its w is the sign just found, made positive.
  e.m = JoinMeet<double>{&p.left, &p.right, &q.left, &q.right, POSITIVE};
  e.i = static_cast<std::uint32_t>(std::min(a, b));
  e.j = static_cast<std::uint32_t>(std::max(a, b));
  const bool ahead = compare_events(e, current_) == POSITIVE;
  // Waiting already when it lies on the other line of the crossing q pending on one of the two
  // (that one's line meets the other line in one front point): then the second learns q too.
  const auto u = static_cast<std::uint32_t>(under), o = static_cast<std::uint32_t>(over);
  const auto waits = [&](Pending q, std::uint32_t learns, std::uint32_t through) {
    if (q.id == kNoSlot || orient(pieces_[q.other].left, pieces_[q.other].right, e.m) != ZERO) return false;
    learn(learns, {q.id, through});
    return true;
  };
  // Or pushed for them before, and a third segment passed between them since: ahead, it waits.
  const auto pushed = [&](std::uint32_t s, std::uint32_t t) {
    return before_[s].id != kNoSlot && before_[s].other == t;
  };
  if (ahead && !pushed(u, o) && !pushed(o, u) && !waits(pa, o, u) && !waits(pb, u, o)) {
    if (taken_.size() >= kNoSlot) throw std::length_error("sweep: too many crossings");
    e.id = static_cast<std::uint32_t>(taken_.size());
    taken_.push_back(0);
    heap_.push_back(e);
    std::push_heap(heap_.begin(), heap_.end(), Later{this});
    learn(u, {e.id, o});
    learn(o, {e.id, u});
  }
  tell(tr, trace::Event::neighbours, {under, over}, {}, ahead ? POSITIVE : NEGATIVE);
}

template <class H>
void Sweep::handle(const Event& e, const std::uint32_t* upper_begin, const std::uint32_t* upper_end,
                   std::vector<IntersectionPoint>& out, H& tr) {
  current_ = e;
  // The segments of the status through e: one run. For a crossing alone the run holds i, and
  // is found from i's place without a search; else from the first segment not below e. A
  // segment ends at e only if e is an endpoint: a crossing equal to an endpoint is taken with it.
  lower_.clear();
  inner_.clear();
  auto first = status_.end();
  if (e.p) {
    first = status_.lower_bound(Probe{});
  } else {
    first = where_[e.i];
    while (first != status_.begin() && side_of_event(*std::prev(first)) == ZERO) --first;
  }
  auto above = first;  // then the first segment above e, or the end
  for (; above != status_.end() && side_of_event(*above) == ZERO; ++above) {
    const bool ends = e.p && compare_xy(pieces_[*above].right, *e.p) == ZERO;
    (ends ? lower_ : inner_).push_back(*above);
  }
  const std::size_t n_upper = static_cast<std::size_t>(upper_end - upper_begin);
  if (n_upper + lower_.size() + inner_.size() >= 2) {
    bool report = n_upper > 0 || !lower_.empty();
    for (std::size_t k = 1; !report && k < inner_.size(); ++k) {
      const Piece &p = pieces_[inner_[0]], &q = pieces_[inner_[k]];
      report = p.vertical != q.vertical || turn(p.left, p.right, q.left, q.right) != ZERO;
    }
    if (report) {
      IntersectionPoint ip{reduced(e.p ? to_exact(*e.p) : to_exact(e.m)), {}};
      ip.segments.assign(upper_begin, upper_end);
      ip.segments.insert(ip.segments.end(), lower_.begin(), lower_.end());
      ip.segments.insert(ip.segments.end(), inner_.begin(), inner_.end());
      std::sort(ip.segments.begin(), ip.segments.end());
      out.push_back(std::move(ip));
      tell(tr, [&] {
        trace::Report r = trace::about(trace::Event::found, {});
        r.point = &out.back().point;
        r.chain = out.back().segments;
        return r;
      });
    }
  }
  for (std::size_t i : lower_) status_.erase(where_[i]);
  for (std::size_t i : inner_) {  // put back below, no allocation; a crossing pending on it is e
    pieces_[i].pending = Pending{};
    slot_[i] = static_cast<std::uint32_t>(moved_.size());
    moved_.push_back(status_.extract(where_[i]));
  }
  // The segments through e that go on, in their order just right of e, each put just below
  // `above` (std::set's hint: no search when it is right, and right when they come in order).
  order_.clear();
  for (const std::uint32_t* i = upper_begin; i != upper_end; ++i)
    if (!pieces_[*i].point) order_.push_back(*i);
  order_.insert(order_.end(), inner_.begin(), inner_.end());
  for (std::size_t i : order_) pieces_[i].through = true;  // every key compared below
  std::sort(order_.begin(), order_.end(), [this](std::size_t a, std::size_t b) { return below(a, b); });
  for (std::size_t i : order_)  // each found by its slot: n segments through one point cost O(n log n), not n²
    where_[i] = slot_[i] != kNoSlot ? status_.insert(above, std::move(moved_[slot_[i]])) : status_.insert(above, i);
  for (std::size_t i : inner_) slot_[i] = kNoSlot;
  for (std::size_t i : order_) pieces_[i].through = false;
  moved_.clear();
  if constexpr (trace::traced<H>) {  // the status after e, lent as a list
    const ExactPoint at = reduced(e.p ? to_exact(*e.p) : to_exact(e.m));
    const std::vector<std::size_t> now(status_.begin(), status_.end());
    trace::Report r = trace::about(trace::Event::sweep, {}, now);
    r.point = &at;
    r.through = order_;
    tr(r);
  }
  if (order_.empty()) {
    if (above != status_.begin() && above != status_.end()) check(*std::prev(above), *above, tr);
    return;
  }
  const auto lo = where_[order_.front()], hi = where_[order_.back()];
  if (lo != status_.begin()) check(*std::prev(lo), *lo, tr);
  if (std::next(hi) != status_.end()) check(*hi, *std::next(hi), tr);
}

template <class H>
std::vector<IntersectionPoint> Sweep::run(H& tr) {
  std::vector<IntersectionPoint> out;
  std::size_t g = 0;
  while (g < groups_.size() || !heap_.empty()) {
    Event e;
    const std::uint32_t *upper_begin = nullptr, *upper_end = nullptr;
    bool endpoint = heap_.empty();
    if (!endpoint && g < groups_.size()) {
      Event first;
      first.p = groups_[g].p;
      first.i = groups_[g].segment;
      endpoint = compare_events(first, heap_.front()) != POSITIVE;
    }
    if (endpoint) {
      e.p = groups_[g].p;
      e.i = groups_[g].segment;
      upper_begin = starts_.data() + groups_[g].begin;
      upper_end = starts_.data() + groups_[g].end;
      ++g;
    } else {
      e = heap_.front();
    }
    while (!heap_.empty() && compare_events(heap_.front(), e) == ZERO) {  // every copy of e
      taken_[heap_.front().id] = 1;
      std::pop_heap(heap_.begin(), heap_.end(), Later{this});
      heap_.pop_back();
    }
    handle(e, upper_begin, upper_end, out, tr);
  }
  return out;
}

}  // namespace plane_sweep

std::vector<IntersectionPoint> intersections_sweep(const std::vector<Segment>& segments) {
  NoTrace none;
  return plane_sweep::Sweep(segments).run(none);
}

std::vector<IntersectionPoint> intersections_sweep(const std::vector<Segment>& segments,
                                                   const trace::AnyHook& hook) {
  return plane_sweep::Sweep(segments).run(hook);
}

}  // namespace t2
