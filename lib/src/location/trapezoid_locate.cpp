// Point location in a subdivision of T² by one trapezoidal map per closed side
// (trapezoid_locate.hpp).
#include "t2/location/trapezoid_locate.hpp"

#include <cmath>

#include "t2/kernel/lexicographic.hpp"

namespace t2 {

using Index = Subdivision::Index;

namespace {
// The side of p: 0 front, 1 back, -1 on Ω.
int side_of(const Point& p) { return p.w() > 0 ? 0 : p.w() < 0 ? 1 : -1; }

// A hook that hears a map's reports as reports about the vertices of S (a chart's `vertex`).
trace::AnyHook about_vertices(const std::vector<Index>& vertex, const trace::AnyHook& hook) {
  return [&vertex, &hook](const trace::Report& r) {
    trace::Report t = r;
    for (auto& i : t.at)
      if (i != trace::Report::none) i = vertex[i];
    t.input_of = vertex;
    hook(t);
  };
}
}  // namespace

TrapezoidLocator::TrapezoidLocator(const Subdivision& S, std::uint64_t seed)
    : TrapezoidLocator(S, seed, trace::AnyHook{}) {}

TrapezoidLocator::TrapezoidLocator(const Subdivision& S, std::uint64_t seed,
                                   const trace::AnyHook& hook)
    : S_(S) {
  build(front, seed, hook);
  build(back, seed + 1, hook);
}

//> trapezoid-chart
void TrapezoidLocator::build(Side s, std::uint64_t seed, const trace::AnyHook& hook) {
  const auto& P = S_.points();
  // Closed: no edge joins a point of the open side to a point off it.
  for (Index h = 0; h < S_.half_edges(); ++h)
    if ((side_of(P[S_.org(h)]) == s) != (side_of(P[S_.dest(h)]) == s)) return;
  Chart& c = charts_[s];
  std::vector<Point> points;
  std::vector<Index> id(P.size(), TrapezoidMap::none);
  for (Index v = 0; v < P.size(); ++v)
    if (side_of(P[v]) == s) {
      id[v] = static_cast<Index>(points.size());
      points.push_back(s == front ? P[v] : antipode(P[v]));
      c.vertex.push_back(v);
    }
  // The point (M, 0) of the chart, right of every vertex: M a power of two, so M·w is
  // exact.
  double M = 1;
  for (const Point& p : points)
    while (!(M * p.w() > p.x())) M *= 2;
  if (!std::isfinite(M)) return;  // no such double: the walk answers this side
  c.unbounded = locate_brute(S_, s == front ? Point(1, M, 0) : Point(-1, -M, 0));
  // One segment per edge; the region on its upper side in the chart. The face of h is on
  // the left of org → dest; on the back the antipode reverses orientations, so there it
  // is on the right. Left of a segment running left to right (in the x-order) is its
  // upper side.
  std::vector<std::pair<Index, Index>> segments;
  for (Index h = 0; h < S_.half_edges(); ++h) {
    const Index a = S_.org(h), b = S_.dest(h), t = S_.twin(h);
    if (id[a] == TrapezoidMap::none || (t != Subdivision::none && t < h)) continue;
    segments.push_back({id[a], id[b]});
    c.half_edge.push_back(h);
    const bool rightward = compare_xy(points[id[a]], points[id[b]]) == NEGATIVE;
    const Index g =
        rightward == (s == front) ? h : t;  // the half-edge whose face is above
    c.above.push_back(g == Subdivision::none
                          ? Location{}
                          : Location{Location::Kind::face, S_.face(g), 0});
  }
  try {
    if (hook)
      c.map.emplace(std::move(points), std::move(segments), seed,
                    about_vertices(c.vertex, hook));
    else
      c.map.emplace(std::move(points), std::move(segments), seed);
  } catch (const SegmentError& e) {
    throw MapError(S_.face(c.half_edge[e.segment()]),
                   std::string("its edges and another face's: ") + e.what());
  }
}
//< trapezoid-chart

//> trapezoid-answer
Location TrapezoidLocator::answer(const Point& p, const trace::AnyHook* hook) const {
  const int s = side_of(p);
  if (s < 0 || !charts_[s].map) {
    if (S_.half_edges() == 0) return Location{};
    return hook ? walk(S_, p, S_.org(0), *hook) : walk(S_, p, S_.org(0));
  }
  const Chart& c = charts_[s];
  const Point q = s == front ? p : antipode(p);
  const TrapezoidMap::Hit h =
      hook ? c.map->locate(q, about_vertices(c.vertex, *hook)) : c.map->locate(q);
  switch (h.kind) {
    case TrapezoidMap::Hit::Kind::point:
      return at_vertex(S_, c.vertex[h.id]);
    case TrapezoidMap::Hit::Kind::segment:
      return at_edge(S_, c.half_edge[h.id]);
    case TrapezoidMap::Hit::Kind::trapezoid:
      break;
  }
  return h.below == TrapezoidMap::none ? c.unbounded : c.above[h.below];
}
//< trapezoid-answer

Location TrapezoidLocator::locate(const Point& p) const { return answer(p, nullptr); }

Location TrapezoidLocator::locate(const Point& p, const trace::AnyHook& hook) const {
  return answer(p, &hook);
}

}  // namespace t2
