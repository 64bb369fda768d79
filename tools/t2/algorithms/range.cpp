// Range search (chapter 15, t2/range/), timed by `t2 bench kdtree` and `t2 bench rangetree`
// (the problem `range`): building the structure on the points and reporting the points of
// every window (range_windows, made before the clock starts, the same for the worker's peers). The answer's size is the number of reports summed
// over the windows, which every exact implementation shares.
#include "algorithms/range.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <random>

#include "algorithms/answer.hpp"
#include "algorithms/registry.hpp"
#include "t2/kernel/bbox.hpp"
#include "t2/range/kdtree.hpp"
#include "t2/range/range_tree.hpp"
#include "t2/trace/overlay.hpp"
#include "t2/trace/recording.hpp"

namespace t2cli::algorithms {

std::vector<std::array<double, 4>> range_windows(std::span<const t2::Point> points) {
  double x0 = 0, x1 = 0, y0 = 0, y1 = 0;
  if (!points.empty()) x0 = x1 = points[0].x(), y0 = y1 = points[0].y();
  for (const auto& p : points) {
    x0 = std::min(x0, p.x()), x1 = std::max(x1, p.x());
    y0 = std::min(y0, p.y()), y1 = std::max(y1, p.y());
  }
  const std::size_t m = std::max<std::size_t>(1, points.size() / 10);
  const double f = 1 / std::sqrt(double(m)), hx = (x1 - x0) * f / 2, hy = (y1 - y0) * f / 2;
  std::mt19937_64 rng(0x1515);
  std::uniform_real_distribution<double> X(x0, x1), Y(y0, y1);
  std::vector<std::array<double, 4>> W;
  W.reserve(m);
  for (std::size_t k = 0; k < m; ++k) {
    const double cx = X(rng), cy = Y(rng);
    W.push_back({cx - hx, cy - hy, cx + hx, cy + hy});
  }
  return W;
}

std::optional<t2::ExactIsoRect> animation_window(std::span<const t2::Point> points) {
  int side = -1;  // the front side if it has points, else the back
  for (const auto& p : points)
    if (p.w() > 0) side = 0;
    else if (p.w() < 0 && side < 0) side = 1;
  if (side < 0) return std::nullopt;
  double x0 = 0, x1 = 0, y0 = 0, y1 = 0;
  bool any = false;
  for (const auto& p : points) {
    if (side < 0 || (side == 0 ? !(p.w() > 0) : !(p.w() < 0))) continue;
    const double x = p.x() / p.w(), y = p.y() / p.w();
    if (!any) x0 = x1 = x, y0 = y1 = y, any = true;
    x0 = std::min(x0, x), x1 = std::max(x1, x), y0 = std::min(y0, y), y1 = std::max(y1, y);
  }
  const double dx = (x1 - x0) / 4, dy = (y1 - y0) / 4;
  t2::Point a = t2::Point::cartesian(x0 + dx, y0 + dy), c = t2::Point::cartesian(x1 - dx, y1 - dy);
  if (side == 1) a = t2::antipode(a), c = t2::antipode(c);
  return t2::iso_rect(t2::to_exact(a), t2::to_exact(c));
}

namespace {

T2_PROBLEM({"range", "reported points", Input::plane});

// The timed run of structure S: built on the points, then every window reported.
template <class S>
Timed range_run(BenchInput& in) {
  auto R = std::make_shared<std::vector<t2::ExactIsoRect>>();
  for (const auto& w : range_windows(in.points))
    R->push_back(t2::iso_rect(t2::to_exact(t2::Point::cartesian(w[0], w[1])),
                              t2::to_exact(t2::Point::cartesian(w[2], w[3]))));
  return [&P = in.points, R] {
    const S tree(P);
    std::size_t k = 0;
    for (const auto& r : *R) k += tree.report(r).size();
    return k;
  };
}

namespace tr = t2::trace;
constexpr std::size_t kNone = tr::Report::none;

// A node of the implicit kd-tree of one side (kdtree.hpp): positions [lo, hi) of tree_order,
// its depth, and the split points (input indices) that bound its cell: x below, x above, y
// below, y above (kNone: unbounded).
struct KdCell {
  std::size_t lo, hi;
  int depth;
  std::array<std::size_t, 4> bound;
};

// The drawn triple (w > 0) of point i: the point itself on the front, its antipode on the back.
t2::Point drawn(const Points& P, std::size_t i) { return P[i].w() > 0 ? P[i] : t2::antipode(P[i]); }

// The point drawn at (x, y) of side `side`, given homogeneously with w > 0 as (w, x, y).
t2::Point on_side(int side, const t2::Point& p) { return side ? t2::antipode(p) : p; }

// The split of node c with splitting point s (input index), axis a: the line through s parallel
// to the other axis, cut by the cell. Each end has s's own w and the coordinate on the axis a
// (so all three are exactly on one line); the other coordinate is the bound's, w times its drawn
// value (exact when both weights are 1), or a point of Omega when the cell is unbounded there.
void add_split(const Points& P, int side, const KdCell& c, std::size_t s, t2::Scene& o) {
  const int a = c.depth % 2;
  const t2::Point sp = drawn(P, s);
  const auto end = [&](int k) {  // k = 0 the lower end, 1 the upper
    const std::size_t b = c.bound[2 * (1 - a) + k];
    const double dir = k ? 1 : -1;
    if (b == kNone) return a == 0 ? t2::Point(0, 0, dir) : t2::Point(0, dir, 0);
    const t2::Point t = drawn(P, b);
    return a == 0 ? t2::Point(sp.w(), sp.x(), sp.w() * (t.y() / t.w()))
                  : t2::Point(sp.w(), sp.w() * (t.x() / t.w()), sp.y());
  };
  const t2::Point e0 = on_side(side, end(0)), e1 = on_side(side, end(1));
  if (e0 == t2::antipode(e1)) {
    tr::add_line(o, on_side(side, sp), e1);
    o.lines.back().style.arrow = false;
  } else if (e0 != e1) {
    tr::add_segment(o, e0, e1);
  }
}

// The cell of c as a polygon of T² (corners at infinity on Omega; where two corners are
// antipodal, the bound's split point between them).
void add_cell(const Points& P, int side, const KdCell& c, t2::Scene& o) {
  const auto corner = [&](int i, int j) {  // i, j: 0 below, 1 above on x, y
    const std::size_t bx = c.bound[i], by = c.bound[2 + j];
    const double X = bx == kNone ? 0 : drawn(P, bx).x() / drawn(P, bx).w();
    const double Y = by == kNone ? 0 : drawn(P, by).y() / drawn(P, by).w();
    if (bx != kNone && by != kNone) return t2::Point::cartesian(X, Y);
    return t2::Point(0, bx == kNone ? (i ? 1 : -1) : 0, by == kNone ? (j ? 1 : -1) : 0);
  };
  const std::array<std::array<int, 2>, 4> around{{{0, 0}, {1, 0}, {1, 1}, {0, 1}}};
  const std::array<std::size_t, 4> side_bound{c.bound[2], c.bound[1], c.bound[3], c.bound[0]};  // after corner k
  t2::ScenePolygon g;
  for (int k = 0; k < 4; ++k) {
    const t2::Point a = corner(around[k][0], around[k][1]), b = corner(around[(k + 1) % 4][0], around[(k + 1) % 4][1]);
    if (g.vertices.empty() || g.vertices.back().point != on_side(side, a)) g.vertices.push_back(tr::overlay_point(on_side(side, a)));
    if (a == t2::antipode(b) && side_bound[k] != kNone)
      g.vertices.push_back(tr::overlay_point(on_side(side, drawn(P, side_bound[k]))));
  }
  if (g.vertices.size() > 1 && g.vertices.back().point == g.vertices.front().point) g.vertices.pop_back();
  if (side) std::reverse(g.vertices.begin(), g.vertices.end());  // the antipode turns it clockwise
  g.style.color = g.style.fill = "#ff7f0e";  // the player's colour of the triangles in focus
  g.style.opacity = 0.3;
  if (g.vertices.size() >= 3) o.polygons.push_back(std::move(g));
}

// The window r as a polygon (its four corners, exact: doubles).
void add_window(const t2::ExactIsoRect& r, t2::Scene& o) {
  t2::ScenePolygon g;
  for (int k = 0; k < 4; ++k) g.vertices.push_back(tr::overlay_point(t2::to_double(r.vertex(k))));
  g.style.label = "window";
  g.style.color = g.style.fill = "#2ca02c";
  g.style.opacity = 0.12;
  g.style.width = 2;
  o.polygons.push_back(std::move(g));
}

// The answer of the animation as a scene: the points in the window (the untraced report).
t2::Scene kdtree_scene(const Points& P) {
  t2::Scene out;
  if (const auto r = animation_window(P))
    for (const std::size_t i : t2::KdTree(std::span<const t2::Point>(P)).report(*r))
      tr::add_point(out, P[i], fmt::format("p{}", i));
  return out;
}

// The kd-tree recorded: the splits of each level (lecture), then the window query: each node
// entered (debugging) and the points reported (the answer).
void record_kdtree(const Points& P, const std::string& name, tr::Recording& rec) {
  const std::optional<t2::ExactIsoRect> r = animation_window(P);
  if (!r)
    throw t2::Undefined(fmt::format("{}: no point off Omega: the window of t2 animate kdtree is the middle half of "
                                    "the bounding box of the points of one side",
                                    name));
  const t2::KdTree T{std::span<const t2::Point>(P)};
  std::size_t omega = 0;
  for (const auto& p : P) omega += p.w() == 0;
  t2::Scene base;
  add_window(*r, base);
  const int wside = r->a().w() > 0 ? 0 : 1;
  tr::Step first = make_step(
      "tree",
      fmt::format("The kd-tree: one tree per side of T2 ({} front points, {} back points; {} points of Omega are kept "
                  "apart by direction), a leaf of at most {} points. The query window: the middle half of the "
                  "bounding box of the {} points, [{}, {}] x [{}, {}].",
                  T.tree_order(0).size(), T.tree_order(1).size(), omega, t2::KdTree::kLeaf,
                  wside ? "back" : "front", r->vertex(0).x().get_d() / r->vertex(0).w().get_d(),
                  r->vertex(2).x().get_d() / r->vertex(2).w().get_d(), r->vertex(0).y().get_d() / r->vertex(0).w().get_d(),
                  r->vertex(2).y().get_d() / r->vertex(2).w().get_d()),
      "");
  first.overlay = base;
  rec.add(first);
  // The splits, level by level (both sides at once).
  std::vector<KdCell> level;
  std::vector<int> level_side;
  for (int s = 0; s < 2; ++s)
    if (!T.tree_order(s).empty()) {
      level.push_back({0, T.tree_order(s).size(), 0, {kNone, kNone, kNone, kNone}});
      level_side.push_back(s);
    }
  std::vector<std::vector<KdCell>> cells(2);  // every node, per side
  t2::Scene splits = base;
  for (int depth = 0; !level.empty(); ++depth) {
    std::vector<KdCell> next;
    std::vector<int> next_side;
    tr::Step st = make_step("level", "", "");
    for (std::size_t k = 0; k < level.size(); ++k) {
      const KdCell& c = level[k];
      const int side = level_side[k];
      cells[side].push_back(c);
      if (c.hi - c.lo <= t2::KdTree::kLeaf) continue;
      const std::size_t mid = c.lo + (c.hi - c.lo) / 2, s = T.tree_order(side)[mid].index;
      add_split(P, side, c, s, splits);
      st.points.push_back(s);
      const int a = depth % 2;
      KdCell lo{c.lo, mid, depth + 1, c.bound}, hi{mid + 1, c.hi, depth + 1, c.bound};
      lo.bound[2 * a + 1] = s, hi.bound[2 * a] = s;
      next.push_back(lo), next.push_back(hi), next_side.push_back(side), next_side.push_back(side);
    }
    if (st.points.empty()) break;
    st.text = fmt::format("Depth {}: {} nodes split at the median of their points by {} through {}; the points "
                          "before it go left, those after it right.",
                          depth, st.points.size(), depth % 2 ? "y (horizontal lines)" : "x (vertical lines)",
                          point_list(st.points));
    st.overlay = splits;
    rec.add(std::move(st));
    level.swap(next), level_side.swap(next_side);
  }
  // The query.
  std::vector<std::size_t> found;
  const auto hook = [&](const tr::Report& e) {
    if (e.event == tr::Event::kd_report) {
      found.push_back(e.at[0]);
      return;
    }
    if (e.event != tr::Event::kd_enter) return;
    const int side = static_cast<int>(e.at[1]);
    const std::size_t lo = e.faces[0], hi = e.faces[1];
    const auto it = std::find_if(cells[side].begin(), cells[side].end(),
                                 [&](const KdCell& c) { return c.lo == lo && c.hi == hi; });
    tr::Step s = make_step("node", "", "");
    s.depth = tr::Depth::debugging;
    s.overlay = splits;
    if (it != cells[side].end() && it->depth > 0) add_cell(P, side, *it, s.overlay);
    const std::string where = fmt::format("The node of {} points at depth {}", hi - lo, e.at[2]);
    if (e.sign == t2::POSITIVE) {
      s.text = where + ": its cell lies inside the window, so all its points are reported without a test.";
      for (std::size_t k = lo; k < hi; ++k) s.points.push_back(T.tree_order(side)[k].index);
    } else if (e.at[0] == kNone) {
      s.text = where + ", a leaf: each of its points is tested against the window.";
      for (std::size_t k = lo; k < hi; ++k) s.points.push_back(T.tree_order(side)[k].index);
    } else {
      s.text = fmt::format("{}: its cell meets the window; it splits at p{}, which is tested, and the query goes on "
                           "into the sides of the split that the window reaches.",
                           where, e.at[0]);
      s.points = {e.at[0]};
    }
    s.text += fmt::format(" Reported so far: {}.", found.size());
    rec.add(std::move(s));
  };
  const std::vector<std::size_t> in = T.report(*r, hook);
  tr::Step last = make_step("answer",
                            in.empty() ? std::string("The window holds no point.")
                                       : fmt::format("The window holds {} points: {}.", in.size(), point_list(in)),
                            "");
  last.points = in;
  last.overlay = splits;
  rec.add(std::move(last));
}

T2_ALGORITHM({.name = "kdtree",
              .problem = "range",
              .summary = "t2::KdTree: a kd-tree per side of T2, O(sqrt n + k) a window (built, then n/10 windows)",
              .title = "range search with a kd-tree: its splits, then the middle half of the points' bounding box",
              .run = kdtree_scene,
              .record = record_kdtree,
              .time = range_run<t2::KdTree>,
              .peers = {"nanoflann", "rtree", "rangetree"}});

T2_ALGORITHM({.name = "rangetree",
              .problem = "range",
              .summary = "t2::RangeTree: a range tree with fractional cascading, O(log n + k) a window",
              .title = "range search with a range tree",
              .time = range_run<t2::RangeTree>});

}  // namespace
}  // namespace t2cli::algorithms
