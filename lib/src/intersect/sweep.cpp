// Bentley–Ottmann on front segments (chapter 13), with exact events and an exact status order.
//
// Events are the points of the queue, in the xy order of lexicographic.hpp: the input endpoints
// (exact integer points) and the meets of two segments' lines, kept as the pair of lines
// (t2/kernel/meet_point.hpp): compared without being constructed. Equal events are one event,
// whatever their form. The status is a std::set of segment indices ordered at the current event
// E. Its invariant, between two events, is: the segments of the status are the segments that
// meet the sweep line x = E.x at or after E (ordered lexicographically, a vertical segment is
// met where its points lie), sorted bottom to top by where they meet it; segments through one
// point of that line are sorted by their order just right of it (by slope), a vertical one last,
// and collinear ones by index. The invariant holds because every point where two segments swap
// is an event (the classic lemma: two segments are adjacent in the status just before their
// leftmost common point), and at each event every segment through it is taken out and put back.
//
// The comparator therefore only ever has to order a segment through E against another one: a
// segment not through E is below or above E (`side` of E on its line), two segments through E
// compare by the sign of w of the meet of their lines (meet.hpp: of the two common points of the
// lines, the one for which they turn counter-clockwise — front, i.e. the first line is below the
// second right of E, exactly when w > 0). std::set only compares the key being inserted with
// the elements, and every key inserted at E goes through E; elements are erased by iterator.
#include <fmt/format.h>

#include <algorithm>
#include <map>
#include <set>
#include <stdexcept>
#include <type_traits>
#include <variant>

#include "t2/intersect/intersections.hpp"
#include "t2/kernel/lexicographic.hpp"
#include "t2/kernel/line.hpp"
#include "t2/kernel/meet_point.hpp"

namespace t2 {
namespace {

using Meet = MeetPoint<Integer>;
using Event = std::variant<ExactPoint, Meet>;

/// compare_xy of two events of either form (meet_point.hpp, lexicographic.hpp).
Sign compare_events(const Event& a, const Event& b) {
  return std::visit([](const auto& p, const auto& q) { return compare_xy(p, q); }, a, b);
}

struct EventLess {
  bool operator()(const Event& a, const Event& b) const { return compare_events(a, b) == NEGATIVE; }
};

/// A front segment from its lower-left end to its upper-right end (the xy order).
struct Piece {
  ExactPoint left{1, 0, 0}, right{1, 0, 0};
  ExactLine line{1, 0, 0};  ///< left ∨ right: positive side above (left for a vertical one)
  bool vertical = false;
  bool point = false;  ///< zero length: never in the status
};

/// The lookup key for "where the current event is" in the status (std::set's transparent search).
struct Probe {};

class Sweep {
 public:
  explicit Sweep(const std::vector<Segment>& segments);
  std::vector<IntersectionPoint> run();

 private:
  struct StatusLess {
    using is_transparent = void;
    const Sweep* s;
    bool operator()(std::size_t a, std::size_t b) const { return s->below(a, b); }
    bool operator()(std::size_t a, Probe) const { return s->side_of_event(a) == POSITIVE; }
    bool operator()(Probe, std::size_t b) const { return s->side_of_event(b) == NEGATIVE; }
  };
  using Status = std::set<std::size_t, StatusLess>;

  Sign side_of_event(std::size_t i) const;
  bool below(std::size_t a, std::size_t b) const;
  void handle(const Event& e, std::vector<std::size_t>& upper, std::vector<IntersectionPoint>& out);
  void check(std::size_t a, std::size_t b);

  std::vector<Piece> pieces_;
  std::map<Event, std::vector<std::size_t>, EventLess> queue_;  // event -> segments starting there
  Event current_;
  Status status_;
  std::vector<Status::iterator> where_;
};

Sweep::Sweep(const std::vector<Segment>& segments)
    : current_(ExactPoint(1, 0, 0)), status_(StatusLess{this}), where_(segments.size()) {
  pieces_.reserve(segments.size());
  for (std::size_t i = 0; i < segments.size(); ++i) {
    const Segment& s = segments[i];
    if (!(s.source().w() > 0 && s.target().w() > 0))
      throw Undefined(fmt::format(
          "segment {} ({}): the sweep takes front segments only (both endpoints with w > 0); the brute force "
          "takes every segment of T2",
          i, to_string(s)));
    Piece p;
    p.left = to_exact(s.source());
    p.right = to_exact(s.target());
    const Sign c = compare_xy(p.left, p.right);
    if (c == POSITIVE) std::swap(p.left, p.right);
    p.point = c == ZERO;
    if (!p.point) {
      p.line = join(p.left, p.right);
      p.vertical = p.line.Y() == 0;  // <W, X, 0>: x is constant
    }
    queue_[Event(p.left)].push_back(i);
    if (!p.point) queue_.try_emplace(Event(p.right));
    pieces_.push_back(std::move(p));
  }
}

/// The side of the current event on segment i's line (positive: the segment is below it). A
/// vertical segment in the status always holds the event (it is there from its lower end to its
/// upper end, and every event in between lies on it): ZERO.
Sign Sweep::side_of_event(std::size_t i) const {
  const Piece& p = pieces_[i];
  if (p.vertical) return ZERO;
  return std::visit([&](const auto& e) { return side(p.line, e); }, current_);
}

bool Sweep::below(std::size_t a, std::size_t b) const {
  if (a == b) return false;
  const Sign sa = side_of_event(a), sb = side_of_event(b);
  if (sa != ZERO && sb != ZERO) throw std::logic_error("sweep: the status compared two segments off the event");
  if (sa != ZERO) return sa == POSITIVE;  // a below the event, b through it
  if (sb != ZERO) return sb == NEGATIVE;  // b above the event, a through it
  const Piece &p = pieces_[a], &q = pieces_[b];
  if (p.vertical || q.vertical) return p.vertical == q.vertical ? a < b : q.vertical;
  const Sign w = turn(p.line, q.line);
  return w != ZERO ? w == POSITIVE : a < b;
}

/// Schedules the crossing of a and b (neighbours in the status) if it comes after the event.
void Sweep::check(std::size_t a, std::size_t b) {
  const Piece &p = pieces_[a], &q = pieces_[b];
  const Sign w = turn(p.line, q.line);
  if (w == ZERO) return;  // parallel or collinear: overlaps are found at their endpoints
  if (!intersects(ExactSegment(p.left, p.right), ExactSegment(q.left, q.right))) return;
  Meet m = w == POSITIVE ? Meet{p.line, q.line} : Meet{q.line, p.line};  // the front one
  Event e(std::move(m));
  if (compare_events(e, current_) == POSITIVE) queue_.try_emplace(std::move(e));
}

void Sweep::handle(const Event& e, std::vector<std::size_t>& upper, std::vector<IntersectionPoint>& out) {
  current_ = e;
  // The segments of the status through e: one run, from the first not below e.
  std::vector<std::size_t> lower, inner;
  for (auto it = status_.lower_bound(Probe{}); it != status_.end() && side_of_event(*it) == ZERO; ++it) {
    const Event r(pieces_[*it].right);
    (compare_events(r, e) == ZERO ? lower : inner).push_back(*it);
  }
  const std::size_t through = upper.size() + lower.size() + inner.size();
  if (through >= 2) {
    bool report = !upper.empty() || !lower.empty();
    for (std::size_t k = 1; !report && k < inner.size(); ++k)
      report = turn(pieces_[inner[0]].line, pieces_[inner[k]].line) != ZERO ||
               pieces_[inner[0]].vertical != pieces_[inner[k]].vertical;
    if (report) {
      IntersectionPoint ip{reduced(std::visit(
                               [](const auto& v) {
                                 if constexpr (std::is_same_v<std::decay_t<decltype(v)>, ExactPoint>) return v;
                                 else return point_of(v);
                               },
                               e)),
                           {}};
      ip.segments = upper;
      ip.segments.insert(ip.segments.end(), lower.begin(), lower.end());
      ip.segments.insert(ip.segments.end(), inner.begin(), inner.end());
      std::sort(ip.segments.begin(), ip.segments.end());
      out.push_back(std::move(ip));
    }
  }
  for (std::size_t i : lower) status_.erase(where_[i]);
  for (std::size_t i : inner) status_.erase(where_[i]);
  bool inserted = false;
  auto insert = [&](std::size_t i) {
    if (pieces_[i].point) return;
    where_[i] = status_.insert(i).first;
    inserted = true;
  };
  for (std::size_t i : upper) insert(i);
  for (std::size_t i : inner) insert(i);
  auto lo = status_.lower_bound(Probe{});  // the first segment through e, or the first above e
  if (!inserted) {
    if (lo != status_.begin() && lo != status_.end()) check(*std::prev(lo), *lo);
    return;
  }
  auto hi = lo;
  while (std::next(hi) != status_.end() && side_of_event(*std::next(hi)) == ZERO) ++hi;
  if (lo != status_.begin()) check(*std::prev(lo), *lo);
  if (std::next(hi) != status_.end()) check(*hi, *std::next(hi));
}

std::vector<IntersectionPoint> Sweep::run() {
  std::vector<IntersectionPoint> out;
  while (!queue_.empty()) {
    auto node = queue_.extract(queue_.begin());
    handle(node.key(), node.mapped(), out);
  }
  return out;
}

}  // namespace

std::vector<IntersectionPoint> intersections_sweep(const std::vector<Segment>& segments) {
  return Sweep(segments).run();
}

}  // namespace t2
