// The kd-tree of points of T² (range/kdtree.hpp).
#include "t2/range/kdtree.hpp"

#include <algorithm>

#include "answer.hpp"
#include "t2/trace/hook.hpp"
#include "window.hpp"

namespace t2 {
namespace {

using range::Window;

// Arranges p[lo, hi) as the subtree of a node of depth `depth` (kdtree.hpp).
void build(std::vector<DrawnPoint>& p, std::size_t lo, std::size_t hi, int depth) {
  //> kdtree-build
  if (hi - lo <= KdTree::kLeaf) return;  // a leaf: scanned by queries
  const int axis = depth % 2;
  const std::size_t mid = lo + (hi - lo) / 2;
  const auto less = [axis](const DrawnPoint& a, const DrawnPoint& b) {
    return range::composite_less(a, b, axis);
  };
  std::nth_element(p.begin() + lo, p.begin() + mid, p.begin() + hi, less);
  build(p, lo, mid, depth + 1);  // before the median in the composite order
  build(p, mid + 1, hi, depth + 1);  // after it
  //< kdtree-build
}

// The flags of the walk: bit 2a + 0 when the region's lower end on axis a is known to be at or
// above the window's, bit 2a + 1 for its upper end at or below the window's.
constexpr unsigned kInside = 0b1111;

template <class Visit>
struct Walker {
  const std::vector<DrawnPoint>& p;
  const Window& w;
  Visit& v;

  //> kdtree-query
  void walk(std::size_t lo, std::size_t hi, int depth, unsigned known) {
    v.enter(lo, hi, depth, known);
    if (known == kInside) return v.all(p.data() + lo, p.data() + hi);  // inside: all
    if (hi - lo <= KdTree::kLeaf) {
      for (std::size_t k = lo; k < hi; ++k)
        if (w.contains(p[k])) v.one(p[k]);
      return;
    }
    const int a = depth % 2;
    const std::size_t mid = lo + (hi - lo) / 2;
    const DrawnPoint& s = p[mid];
    const double c = a ? s.y : s.x;
    const bool left = w.lo[a].at_most(c, s.w);   // lo ≤ s: the points before s may be in
    const bool right = w.hi[a].at_least(c, s.w);  // s ≤ hi: the points after s may be in
    if (left && right && w.contains(s)) v.one(s);
    // The region before s ends at s: inside there when s ≤ hi. The one after starts at s.
    if (left) walk(lo, mid, depth + 1, right ? known | 2u << (2 * a) : known);
    if (right) walk(mid + 1, hi, depth + 1, left ? known | 1u << (2 * a) : known);
  }
  //< kdtree-query
};

// The flags at the root: an infinite end of the window holds the whole tree on that end.
unsigned root_flags(const Window& w) {
  unsigned known = 0;
  for (int a = 0; a < 2; ++a) {
    if (w.lo[a].minus_infinity()) known |= 1u << (2 * a);
    if (w.hi[a].plus_infinity()) known |= 2u << (2 * a);
  }
  return known;
}

struct Counter {
  std::size_t n = 0, nodes = 0;
  void enter(std::size_t, std::size_t, int, unsigned) { ++nodes; }
  void all(const DrawnPoint* b, const DrawnPoint* e) { n += static_cast<std::size_t>(e - b); }
  void one(const DrawnPoint&) { ++n; }
};

struct Reporter {
  std::vector<std::size_t>& out;
  void enter(std::size_t, std::size_t, int, unsigned) {}
  void all(const DrawnPoint* b, const DrawnPoint* e) {
    for (; b != e; ++b) out.push_back(b->index);
  }
  void one(const DrawnPoint& q) { out.push_back(q.index); }
};

// The reporter that tells a hook each node entered (Event::kd_enter) and each point reported
// (Event::kd_report), in input indices (kdtree.hpp).
struct KdTracer {
  const std::vector<DrawnPoint>& p;
  std::size_t side;
  const trace::AnyHook& hook;
  std::vector<std::size_t>& out;
  void enter(std::size_t lo, std::size_t hi, int depth, unsigned known) {
    trace::Report r;
    r.event = trace::Event::kd_enter;
    r.faces = {static_cast<std::uint32_t>(lo), static_cast<std::uint32_t>(hi)};
    if (hi - lo > KdTree::kLeaf) r.at[0] = p[lo + (hi - lo) / 2].index;
    r.at[1] = side;
    r.at[2] = static_cast<std::size_t>(depth);
    r.sign = known == kInside ? POSITIVE : ZERO;
    hook(r);
  }
  void all(const DrawnPoint* b, const DrawnPoint* e) {
    for (; b != e; ++b) one(*b);
  }
  void one(const DrawnPoint& q) {
    out.push_back(q.index);
    hook(trace::about(trace::Event::kd_report, {q.index}));
  }
};

}  // namespace

KdTree::KdTree(std::span<const Point> points) {
  Sides s = split_sides(points);
  for (int k = 0; k < 2; ++k) {
    side_[k] = std::move(s.side[k]);
    build(side_[k], 0, side_[k].size(), 0);
  }
  omega_ = std::move(s.omega);
}

template <class Visit>
void KdTree::walk(const ExactBBox& b, Visit& v) const {
  const Window w(b);
  const std::vector<DrawnPoint>& p = side_[w.side];
  if (p.empty()) return;
  Walker<Visit>{p, w, v}.walk(0, p.size(), 0, root_flags(w));
}

std::size_t KdTree::count(const ExactIsoRect& r) const {
  return range::count_in(r, omega_, [this](const ExactBBox& b) {
    Counter c;
    walk(b, c);
    return c.n;
  });
}

std::vector<std::size_t> KdTree::report(const ExactIsoRect& r) const {
  return range::report_in(r, omega_, [this](const ExactBBox& b, std::vector<std::size_t>& out) {
    Reporter rep{out};
    walk(b, rep);
  });
}

std::vector<std::size_t> KdTree::report(const ExactIsoRect& r,
                                        const trace::AnyHook& hook) const {
  return range::report_in(r, omega_, [&](const ExactBBox& b, std::vector<std::size_t>& out) {
    const Window w(b);
    KdTracer t{side_[w.side], static_cast<std::size_t>(w.side), hook, out};
    walk(b, t);
  });
}

std::size_t KdTree::visits(const ExactIsoRect& r) const {
  Counter c;
  walk(bbox(r), c);
  return c.nodes;
}

}  // namespace t2
