// The two-dimensional range tree with fractional cascading (range/range_tree.hpp).
#include "t2/range/range_tree.hpp"

#include <algorithm>
#include <numeric>

#include "answer.hpp"
#include "window.hpp"

namespace t2 {
namespace {

using range::Window;

struct Builder {
  const std::vector<DrawnPoint>& byx;
  std::vector<std::vector<std::uint32_t>>& level;
  std::vector<std::vector<std::uint32_t>>& bridge;

  // The composite y order of two points given by their positions in byx (which is the
  // composite x order, so a tie in y is broken by x, then by index, as positions compare).
  bool y_less(std::uint32_t u, std::uint32_t v) const {
    const Sign s = range::compare_axis(byx[u], byx[v], 1);
    return s == ZERO ? u < v : s == NEGATIVE;
  }

  //> rangetree-build
  // The node of depth d owning [lo, hi): its y-sorted list and bridges, from its children.
  void build(std::size_t d, std::uint32_t lo, std::uint32_t hi) {
    if (level.size() <= d)  // the first node of depth d
      level.emplace_back(byx.size()), bridge.emplace_back(byx.size());
    if (hi - lo == 1) {
      level[d][lo] = lo, bridge[d][lo] = 0;
      return;
    }
    const std::uint32_t mid = lo + (hi - lo) / 2;
    build(d + 1, lo, mid);
    build(d + 1, mid, hi);
    std::vector<std::uint32_t>& L = level[d];
    const std::vector<std::uint32_t>& C = level[d + 1];  // the children's lists
    std::uint32_t i = lo, j = mid, from_left = 0;
    for (std::uint32_t t = lo; t < hi; ++t) {
      bridge[d][t] = from_left;  // left-child elements before position t
      if (j == hi || (i < mid && y_less(C[i], C[j])))
        L[t] = C[i++], ++from_left;
      else
        L[t] = C[j++];
    }
  }
  //< rangetree-build
};

template <class Visit>
struct CascadeWalker {
  const std::vector<std::vector<std::uint32_t>>& level;
  const std::vector<std::vector<std::uint32_t>>& bridge;
  std::size_t i0, i1;  // the leaves in the x-interval: [i0, i1)
  Visit& v;

  //> rangetree-query
  // The node of depth d owning [lo, hi): its list has the y-interval at [lo + j0, lo + j1).
  void walk(std::size_t d, std::size_t lo, std::size_t hi, std::size_t j0, std::size_t j1) {
    if (j0 == j1 || hi <= i0 || i1 <= lo) return;  // nothing in y, or nothing in x
    const std::uint32_t* list = level[d].data() + lo;
    if (i0 <= lo && hi <= i1) return v.all(list + j0, list + j1);  // canonical: all
    const std::size_t mid = lo + (hi - lo) / 2;
    // The bridge of a prefix of length t: how many of its elements are in the left child.
    auto left = [&](std::size_t t) -> std::size_t {
      return t == hi - lo ? mid - lo : bridge[d][lo + t];
    };
    walk(d + 1, lo, mid, left(j0), left(j1));
    walk(d + 1, mid, hi, j0 - left(j0), j1 - left(j1));
  }
  //< rangetree-query
};

struct CascadeCounter {
  std::size_t n = 0;
  void all(const std::uint32_t* b, const std::uint32_t* e) { n += static_cast<std::size_t>(e - b); }
};

struct CascadeReporter {
  const std::vector<DrawnPoint>& byx;
  std::vector<std::size_t>& out;
  void all(const std::uint32_t* b, const std::uint32_t* e) {
    for (; b != e; ++b) out.push_back(byx[*b].index);
  }
};

}  // namespace

RangeTree::RangeTree(std::span<const Point> points) {
  Sides s = split_sides(points);
  for (int k = 0; k < 2; ++k) {
    Tree& t = side_[k];
    t.byx = std::move(s.side[k]);
    std::sort(t.byx.begin(), t.byx.end(),
              [](const DrawnPoint& a, const DrawnPoint& b) { return range::composite_less(a, b, 0); });
    if (!t.byx.empty())
      Builder{t.byx, t.level, t.bridge}.build(0, 0, static_cast<std::uint32_t>(t.byx.size()));
  }
  omega_ = std::move(s.omega);
}

template <class Visit>
void RangeTree::walk(const ExactBBox& b, Visit& v) const {
  const Window w(b);
  const Tree& t = side_[w.side];
  if (t.byx.empty()) return;
  const auto& P = t.byx;
  // Four binary searches: the x-interval among the leaves, the y-interval in the root's list.
  const auto x_below = [&](const DrawnPoint& p) { return !w.lo[0].at_most(p.x, p.w); };
  const auto x_in = [&](const DrawnPoint& p) { return w.hi[0].at_least(p.x, p.w); };
  const std::size_t i0 = std::partition_point(P.begin(), P.end(), x_below) - P.begin();
  const std::size_t i1 = std::partition_point(P.begin(), P.end(), x_in) - P.begin();
  const auto& root = t.level[0];
  const auto y_below = [&](std::uint32_t k) { return !w.lo[1].at_most(P[k].y, P[k].w); };
  const auto y_in = [&](std::uint32_t k) { return w.hi[1].at_least(P[k].y, P[k].w); };
  const std::size_t j0 = std::partition_point(root.begin(), root.end(), y_below) - root.begin();
  const std::size_t j1 = std::partition_point(root.begin(), root.end(), y_in) - root.begin();
  CascadeWalker<Visit>{t.level, t.bridge, i0, i1, v}.walk(0, 0, P.size(), j0, j1);
}

std::size_t RangeTree::count(const ExactIsoRect& r) const {
  return range::count_in(r, omega_, [this](const ExactBBox& b) {
    CascadeCounter c;
    walk(b, c);
    return c.n;
  });
}

std::vector<std::size_t> RangeTree::report(const ExactIsoRect& r) const {
  return range::report_in(r, omega_, [this](const ExactBBox& b, std::vector<std::size_t>& out) {
    CascadeReporter rep{side_[b.side() == Side::front ? 0 : 1].byx, out};
    walk(b, rep);
  });
}

std::size_t RangeTree::entries() const {
  std::size_t n = 0;
  for (const Tree& t : side_) n += t.level.size() * t.byx.size();
  return n;
}

}  // namespace t2
