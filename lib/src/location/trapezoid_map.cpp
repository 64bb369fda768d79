// The trapezoidal map and its history DAG by randomized incremental construction
// (trapezoid_map.hpp; de Berg et al., chapter 6).
#include "t2/location/trapezoid_map.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <numeric>
#include <random>
#include <stdexcept>

#include "t2/kernel/error.hpp"
#include "t2/kernel/lexicographic.hpp"
#include "t2/kernel/orient.hpp"

namespace t2 {

using Index = TrapezoidMap::Index;

TrapezoidMap::TrapezoidMap(std::vector<Point> points,
                           std::vector<std::pair<Index, Index>> segments,
                           std::uint64_t seed)
    : P_(std::move(points)) {
  NoTrace quiet;
  build(std::move(segments), seed, quiet);
}

TrapezoidMap::TrapezoidMap(std::vector<Point> points,
                           std::vector<std::pair<Index, Index>> segments,
                           std::uint64_t seed, const trace::AnyHook& hook)
    : P_(std::move(points)) {
  build(std::move(segments), seed, hook);
}

template <class H>
void TrapezoidMap::build(std::vector<std::pair<Index, Index>> segments,
                         std::uint64_t seed, H& hook) {
  for (std::size_t i = 0; i < P_.size(); ++i)
    if (!(P_[i].w() > 0))
      throw BadInput(fmt::format("trapezoid map: point {} is not a front point", i));
  for (std::size_t i = 0; i < segments.size(); ++i) {
    auto [a, b] = segments[i];
    if (a >= P_.size() || b >= P_.size() || a == b)
      throw SegmentError(i, fmt::format("segment {} has bad endpoints", i));
    if (compare_xy(P_[a], P_[b]) == POSITIVE) std::swap(a, b);
    seg_.push_back({a, b});
  }
  make(Trapezoid{});  // the whole chart, the root leaf 0
  std::vector<Index> order(seg_.size());
  std::iota(order.begin(), order.end(), Index(0));
  std::mt19937_64 rng(seed);
  std::shuffle(order.begin(), order.end(), rng);
  for (const Index s : order) insert(s, hook);
}

Index TrapezoidMap::make(const Trapezoid& t) {
  const auto id = static_cast<Index>(trap_.size());
  trap_.push_back(t);
  trap_.back().node = static_cast<Index>(node_.size());
  node_.push_back({Node::leaf, id, none, none});
  return id;
}

// `right` is the neighbour of `left` across the part of its right side above its rightp,
// and `left` that of `right` across the part of its left side above its leftp (the same
// point): the two relations always hold together (either may be none).
void TrapezoidMap::link_upper(Index left, Index right) {
  if (left != none) trap_[left].ur = right;
  if (right != none) trap_[right].ul = left;
}
void TrapezoidMap::link_lower(Index left, Index right) {
  if (left != none) trap_[left].lr = right;
  if (right != none) trap_[right].ll = left;
}

//> trapezoid-locate-left
// The trapezoid that segment s enters from its left endpoint p: the DAG descent for p,
// with the ties that p itself causes broken as for a point of s just right of p (de Berg
// et al., §6.2): at p's own x-node go right; at a segment t that starts at p, compare the
// other end q with t.
Index TrapezoidMap::locate_left(Index s) const {
  const Index p = seg_[s].a, q = seg_[s].b;
  Index n = 0;
  for (;;) {
    const Node& v = node_[n];
    if (v.kind == Node::leaf) return v.id;
    if (v.kind == Node::x) {
      n = v.id == p || compare_xy(P_[p], P_[v.id]) == POSITIVE ? v.right : v.left;
      continue;
    }
    const Seg& t = seg_[v.id];
    const Sign o = orient(P_[t.a], P_[t.b], P_[t.a == p ? q : p]);
    if (o == ZERO)
      throw SegmentError(
          s, fmt::format("segments {} and {} overlap, or one ends inside the other", s,
                         v.id));
    n = o == POSITIVE ? v.left : v.right;
  }
}
//< trapezoid-locate-left

Index TrapezoidMap::push(const Node& n) {
  node_.push_back(n);
  return static_cast<Index>(node_.size() - 1);
}

//> trapezoid-insert
template <class H>
void TrapezoidMap::insert(Index s, H& hook) {
  const Index p = seg_[s].a, q = seg_[s].b;
  const Point &P = P_[p], &Q = P_[q];
  // The trapezoids Δ0 … Δk that s crosses, left to right: across the right side of Δj at
  // its point r, s goes on into the lower-right neighbour when r is above s, else the
  // upper-right.
  std::vector<Index> D{locate_left(s)};
  for (;;) {
    const Trapezoid& t = trap_[D.back()];
    if (t.rightp == none || compare_xy(P_[t.rightp], Q) != NEGATIVE) break;
    const Sign o = orient(P, Q, P_[t.rightp]);
    if (o == ZERO)
      throw SegmentError(s, fmt::format("point {} lies inside segment {}", t.rightp, s));
    D.push_back(o == POSITIVE ? t.lr : t.ur);
    if (D.back() ==
        none)  // impossible for valid input: s crosses a segment that ends at r
      throw SegmentError(
          s,
          fmt::format("segment {} crosses another segment near point {}", s, t.rightp));
  }
  const Trapezoid d0 = trap_[D.front()], dk = trap_[D.back()];
  for (const Index t :
       {dk.top, dk.bottom})  // a cheap check that s stays between them at q
    if (t != none && seg_[t].a != q && seg_[t].b != q &&
        orient(P_[seg_[t].a], P_[seg_[t].b], Q) != (t == dk.top ? NEGATIVE : POSITIVE))
      throw SegmentError(s, fmt::format("segments {} and {} cross", s, t));
  // Δ0 loses A, the part left of p (none when p is Δ0's own leftp); the part right of p
  // is cut by s into an upper trapezoid U and a lower one L, which grow to the right.
  const auto first = static_cast<Index>(trap_.size());  // the first new trapezoid
  Index A = none;
  if (d0.leftp != p) {
    A = make({d0.top, d0.bottom, d0.leftp, p});
    link_upper(d0.ul, A);
    link_lower(d0.ll, A);
  }
  Index U = make({d0.top, s, p, none}), L = make({s, d0.bottom, p, none});
  link_upper(A != none ? A : d0.ul, U);
  link_lower(A != none ? A : d0.ll, L);
  std::vector<Index> up{U}, lo{L};  // the new trapezoids over and under each Δj
  for (std::size_t j = 0; j + 1 < D.size(); ++j) {
    const Trapezoid dj = trap_[D[j]], dn = trap_[D[j + 1]];
    const Index r = dj.rightp;
    if (orient(P, Q, P_[r]) == POSITIVE) {  // r above s: U ends at r, L goes on
      trap_[U].rightp = r;
      link_upper(U, dj.ur);
      const Index V = make({dn.top, s, r, none});
      link_lower(U, V);
      link_upper(dn.ul, V);
      U = V;
    } else {  // r below s: L ends at r, U goes on
      trap_[L].rightp = r;
      link_lower(L, dj.lr);
      const Index V = make({s, dn.bottom, r, none});
      link_upper(L, V);
      link_lower(dn.ll, V);
      L = V;
    }
    up.push_back(U), lo.push_back(L);
  }
  // Δk loses B, the part right of q (none when q is Δk's own rightp).
  trap_[U].rightp = trap_[L].rightp = q;
  Index B = none;
  if (dk.rightp != q) {
    B = make({dk.top, dk.bottom, q, dk.rightp});
    link_upper(U, B);
    link_lower(L, B);
  }
  link_upper(B != none ? B : U, dk.ur);
  link_lower(B != none ? B : L, dk.lr);
  // The DAG: the leaf of each Δj becomes the y-node of s over its two new trapezoids,
  // under the x-nodes of p (Δ0, when A exists) and q (Δk, when B exists).
  for (std::size_t j = 0; j < D.size(); ++j) {
    const Index leaf = trap_[D[j]].node;
    trap_[D[j]].node = none;
    Node n{Node::y, s, trap_[up[j]].node, trap_[lo[j]].node};
    if (j + 1 == D.size() && B != none) n = {Node::x, q, push(n), trap_[B].node};
    if (j == 0 && A != none) n = {Node::x, p, trap_[A].node, push(n)};
    node_[leaf] = n;
  }
  tell(hook, [&] {
    trace::Report r = trace::about(trace::Event::trapezoid_split, {p, q});
    r.face_list = D, r.faces = {first, static_cast<Index>(trap_.size())};
    r.trapezoids = this;
    return r;
  });
}
//< trapezoid-insert

//> trapezoid-query
template <class H>
TrapezoidMap::Hit TrapezoidMap::descend(const Point& p, H& hook) const {
  Hit h;
  Index n = 0;
  for (;;) {
    ++h.steps;
    const Node& v = node_[n];
    if (v.kind == Node::leaf) {
      h.id = v.id, h.below = trap_[v.id].bottom;
      tell(hook, [&] { return told(trace::Event::dag_leaf, {}, ZERO, v.id); });
      return h;
    }
    if (v.kind == Node::x) {
      const Sign c = compare_xy(p, P_[v.id]);
      tell(hook, [&] { return told(trace::Event::dag_x, {v.id}, c, 0); });
      if (c == ZERO) return {Hit::Kind::point, v.id, none, h.steps};
      n = c == NEGATIVE ? v.left : v.right;
      continue;
    }
    const Seg& t = seg_[v.id];
    const Sign o = orient(P_[t.a], P_[t.b], p);
    tell(hook, [&] { return told(trace::Event::dag_y, {t.a, t.b}, o, 0); });
    if (o == ZERO) {  // on t's line, in its x-range: inside t (its ends have x-nodes)
      if (compare_xy(P_[t.a], p) != NEGATIVE || compare_xy(p, P_[t.b]) != NEGATIVE)
        throw std::logic_error(
            "trapezoid map: a query on a segment's line out of its range");
      return {Hit::Kind::segment, v.id, none, h.steps};
    }
    n = o == POSITIVE ? v.left : v.right;
  }
}
//< trapezoid-query

trace::Report TrapezoidMap::told(trace::Event e, std::initializer_list<std::size_t> at,
                                 Sign sign, Index trapezoid) const {
  trace::Report r = trace::about(e, at);
  r.sign = sign, r.faces = {trapezoid, 0}, r.trapezoids = this;
  return r;
}

TrapezoidMap::Hit TrapezoidMap::locate(const Point& p) const {
  NoTrace quiet;
  return descend(p, quiet);
}

TrapezoidMap::Hit TrapezoidMap::locate(const Point& p, const trace::AnyHook& hook) const {
  return descend(p, hook);
}

// The longest path, by a depth-first search that finishes each node after its children
// (the DAG shares nodes, so each is finished once and then read).
std::size_t TrapezoidMap::depth() const {
  std::vector<std::size_t> d(node_.size(), 0);
  std::vector<Index> stack{0};
  while (!stack.empty()) {
    const Index n = stack.back();
    const Node& v = node_[n];
    if (v.kind != Node::leaf && d[v.left] == 0) {
      stack.push_back(v.left);
    } else if (v.kind != Node::leaf && d[v.right] == 0) {
      stack.push_back(v.right);
    } else {
      d[n] = v.kind == Node::leaf ? 1 : 1 + std::max(d[v.left], d[v.right]);
      stack.pop_back();
    }
  }
  return d[0];
}

}  // namespace t2
