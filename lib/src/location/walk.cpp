// The walk of seed 000's Algorithm 15 and the brute-force location (walk.hpp).
#include "t2/location/walk.hpp"

#include <cstdint>
#include <optional>
#include <utility>

#include <fmt/format.h>

#include "t2/kernel/filter.hpp"
#include "t2/kernel/orient.hpp"
#include "t2/kernel/point_in_polygon.hpp"
#include "t2/kernel/segment.hpp"
#include "t2/trace/hook.hpp"

namespace t2 {

using Index = Subdivision::Index;

std::string to_string(const Location& l) {
  switch (l.kind) {
    case Location::Kind::face: return fmt::format("face {}", l.face);
    case Location::Kind::edge: return fmt::format("edge {} {}", l.face, l.k);
    case Location::Kind::vertex: return fmt::format("vertex {} {}", l.face, l.k);
    case Location::Kind::outside: break;
  }
  return "outside";
}

Location at_vertex(const Subdivision& S, Index v) {
  Location l{Location::Kind::vertex, Subdivision::outside, 0};
  for (const auto& c : S.corners(v))
    if (c.face < l.face) l.face = c.face, l.k = c.k;
  return l;
}
Location at_edge(const Subdivision& S, Index h) {
  const Index t = S.twin(h);
  if (t != Subdivision::none && S.face(t) < S.face(h)) h = t;
  return {Location::Kind::edge, S.face(h), S.slot(h)};
}

namespace {

// A point Y of the segment qp, given by a line a ∨ b through it that is not q ∨ p: Y is
// (a ∨ b) ∧ (q ∨ p) = α q + β p with (α, β) = s·(D_p, −D_q), D_x = det(a, b, x), α, β ≥ 0.
struct Mark {
  const Point* a;
  const Point* b;
  int s;  // the sign s
};
Mark mark(const Point& a, const Point& b, const Point& q, const Point& p) {
  const int dp = orient(a, b, p);
  return {&a, &b, dp != 0 ? dp : -int(orient(a, b, q))};
}

//> walk-order
// The sign of position(y) − position(x) along the segment (walk.hpp:
// s₁s₂ (D_q² D_p¹ − D_q¹ D_p²) with x first, negated so that POSITIVE means
// y comes after x).
int after(const Mark& x, const Mark& y, const Point& q, const Point& p) {
  const auto order = [](const auto& a1, const auto& b1, const auto& a2, const auto& b2,
                        const auto& u, const auto& v) {
    const auto det = [](const auto& a, const auto& b, const auto& c) {
      return a.w * (b.x * c.y - b.y * c.x) - a.x * (b.w * c.y - b.y * c.w) +
             a.y * (b.w * c.x - b.x * c.w);
    };
    return det(a2, b2, u) * det(a1, b1, v) - det(a1, b1, u) * det(a2, b2, v);
  };
  const Sign e = sign_of_poly(order, *x.a, *x.b, *y.a, *y.b, q, p);
  return -x.s * y.s * int(e);
}
//< walk-order

// Does the segment qp meet the closed edge a b? (walk.hpp: the sign rule, antipodal crossings
// excluded.) Collinear edges are not counted: the walk meets their ends through other edges.
//> walk-meet
bool meets(const Point& a, const Point& b, const Point& q, const Point& p) {
  const int da = orient(q, p, a), db = orient(q, p, b);
  if (da == db) return false;  // both 0 (collinear) or both on one side
  const int s = db != 0 ? db : -da;
  const int dq = orient(a, b, q), dp = orient(a, b, p);
  return (dq == 0 || dq == s) && (dp == 0 || dp == -s);
}
//< walk-meet

// Across the edge h of `region` (one of the face's own half-edges, or a boundary half-edge for
// the complement): the region on its other side, and the half-edge of that region it enters by.
void cross(const Subdivision& S, Index h, Index& region, Index& entry) {
  if (region == Subdivision::outside) {
    region = S.face(h), entry = h;
  } else if (S.twin(h) == Subdivision::none) {
    region = Subdivision::outside, entry = h;
  } else {
    entry = S.twin(h), region = S.face(entry);
  }
}

// The walk's second state: in `region`, entered at the point `here` of the segment qp (through
// the half-edge `entry` of the region, or from a vertex or from a point inside it: none), on to
// the first point of the segment after `here` on an edge of the region, crossing edges while
// they are crossed in their interiors. Returns the answer, or none after setting v to the
// vertex of the segment that the walk reached (the caller goes on in the first state).
// `from` is the vertex the walk leaves into the region, or none. The hook hears each region
// entered (Event::enter_region).
template <class H>
std::optional<Location> through_regions(const Subdivision& S, const Point& q, const Point& p, Index region,
                                        Index entry, Mark here, Index& v, std::vector<Index>* crossed,
                                        Index from, H& hook) {
  const auto& P = S.points();
  for (;;) {
    if (crossed) crossed->push_back(region);
    tell(hook, [&] {
      trace::Report r;
      r.event = trace::Event::enter_region;
      r.faces = {region, 0};
      if (entry != Subdivision::none) {
        r.at[0] = S.org(entry), r.at[1] = S.dest(entry);
      } else if (from != Subdivision::none) {
        r.at[2] = from;
      }
      from = Subdivision::none;
      return r;
    });
    // A convex triangle (Δ(a, b, c) > 0: the small one of its vertices, not the complement)
    // is left by its edge u → w whose ends the line qp separates, u on the right of qp and w
    // on its left (walk.hpp, "Triangles"); p is inside when on the inner side of u → w.
    //> walk-triangle
    if (region != Subdivision::outside && S.convex_triangle(region)) {
      const bool entered = entry != Subdivision::none;
      const Index ab = entered ? entry : S.first(region), bc = S.next(ab), ca = S.next(bc);
      const Point &a = P[S.org(ab)], &b = P[S.org(bc)], &c = P[S.org(ca)];
      Index out = Subdivision::none;
      const int sc = orient(q, p, c);
      if (entered && sc == 0) {  // in through ab, the segment runs into c
        if (p == c) return at_vertex(S, S.org(ca));
        if (orient(b, c, p) == POSITIVE) return Location{Location::Kind::face, region, 0};
        v = S.org(ca);
        return std::nullopt;
      }
      const int sa = orient(q, p, a);
      if (entered) {  // a, b on opposite sides: out by bc if c is on a's side, else by ca
        out = sc == sa ? bc : ca;
      } else if (const int sb = orient(q, p, b); sa != 0 && sb != 0 && sc != 0) {
        out = sa < 0 && sb > 0 ? ab : sb < 0 && sc > 0 ? bc : ca;
      }  // else the line qp passes through a vertex: the general step below
      if (out != Subdivision::none) {
        const Point &u = P[S.org(out)], &w = P[S.dest(out)];
        const int o = orient(u, w, p);
        if (o > 0) return Location{Location::Kind::face, region, 0};
        if (o == 0) return at_edge(S, out);
        here = Mark{&u, &w, o};  // mark(u, w, q, p), as D_p = o is not 0
        cross(S, out, region, entry);
        continue;
      }
    }
    //< walk-triangle
    Index best = Subdivision::none;
    Mark bm{};
    const auto visit = [&](Index h) {
      if (h == entry) return;
      const Point &a = P[S.org(h)], &b = P[S.dest(h)];
      if (!meets(a, b, q, p)) return;
      const Mark m = mark(a, b, q, p);
      if (after(here, m, q, p) <= 0) return;
      if (best == Subdivision::none || after(m, bm, q, p) > 0) best = h, bm = m;
    };
    if (region == Subdivision::outside) {
      for (const Index h : S.boundary()) visit(h);
    } else {
      for (Index h = S.first(region); h < S.first(region) + S.size(region); ++h) visit(h);
    }
    if (best == Subdivision::none)
      return region == Subdivision::outside ? Location{} : Location{Location::Kind::face, region, 0};
    const Index a = S.org(best), b = S.dest(best);
    const bool at_p = orient(P[a], P[b], p) == ZERO;
    if (orient(q, p, P[a]) == ZERO) {
      if (at_p) return at_vertex(S, a);
      v = a;
      return std::nullopt;
    }
    if (orient(q, p, P[b]) == ZERO) {
      if (at_p) return at_vertex(S, b);
      v = b;
      return std::nullopt;
    }
    if (at_p) return at_edge(S, best);
    cross(S, best, region, entry);
    here = bm;
  }
}

//> walk-visibility
// The visibility walk (walk.hpp): from face f, across an edge of the current triangle
// with p strictly on its outer side (the edge entered by is not tested again, and a coin
// picks which of the other two goes first), until p is on the inner side of all three:
// then p is in the closed triangle, and the edges through it say where. Gives up (none)
// at a face that is not a convex triangle, at a boundary edge, or after as many steps as
// the map has faces.
std::optional<Location> visibility_walk(const Subdivision& S, const Point& p, Index f) {
  const auto& P = S.points();
  Index entry = Subdivision::none;
  std::uint32_t coin = 0x9E3779B9u;
  for (std::size_t step = 0; step <= S.faces(); ++step) {
    if (!S.convex_triangle(f)) return std::nullopt;
    const Index h = S.first(f);  // half-edge h + k runs from vertex k to vertex k + 1
    const Point* v[3] = {&P[S.org(h)], &P[S.org(h + 1)], &P[S.org(h + 2)]};
    coin = coin * 1664525u + 1013904223u;  // a linear congruential generator
    const Index k0 = entry == Subdivision::none ? 0 : (entry - h + 1) % 3;
    Index order[3] = {k0, (k0 + 1) % 3, (k0 + 2) % 3};  // the last: the entry, if any
    if (coin >> 31) std::swap(order[0], order[1]);
    Index zero[2] = {0, 0};
    int zeros = 0;
    bool crossed = false;
    for (int i = 0; i < (entry == Subdivision::none ? 3 : 2); ++i) {
      const Index k = order[i];
      const Sign o = orient(*v[k], *v[(k + 1) % 3], p);
      if (o == ZERO) zero[zeros++] = h + k;
      if (o != NEGATIVE) continue;
      if (S.twin(h + k) == Subdivision::none) return std::nullopt;  // the complement
      entry = S.twin(h + k), f = S.face(entry), crossed = true;
      break;
    }
    if (crossed) continue;
    if (zeros == 0) return Location{Location::Kind::face, f, 0};
    if (zeros == 1) return at_edge(S, zero[0]);
    const Index a = zero[0] - h, b = zero[1] - h;  // two edges through p: their vertex
    return at_vertex(S, S.org(h + ((a + 1) % 3 == b ? b : a)));
  }
  return std::nullopt;
}
//< walk-visibility

// The walk's first state, from vertex v of the segment qp (v != p), alternating with the second.
// The hook hears each vertex (Event::reach_vertex) and each region entered.
template <class H>
Location from_vertex(const Subdivision& S, const Point& q, const Point& p, Index v, std::vector<Index>* crossed,
                     H& hook) {
  const auto& P = S.points();
  const Point r = detail::off_line_point(q, p);
  for (;;) {
    tell(hook, trace::Event::reach_vertex, {std::size_t(v)});
    const Point& V = P[v];
    Index region = Subdivision::outside, along = Subdivision::none;
    for (const auto& c : S.corners(v)) {
      const Index h = S.first(c.face) + c.k;
      for (const Index e : {h, S.prev(h)}) {
        const Index x = e == h ? S.dest(e) : S.org(e);
        if (on_segment(V, P[x], p)) return P[x] == p ? at_vertex(S, x) : at_edge(S, e);
        if (on_segment(V, p, P[x])) along = x;
      }
      if (region == Subdivision::outside && in_corner(P[S.org(S.prev(h))], V, P[S.dest(h)], p)) region = c.face;
    }
    if (along != Subdivision::none) {
      v = along;
      continue;
    }
    // In `region`, from V: the first point of the segment after V on one of its edges.
    const Index at = v;
    if (auto l = through_regions(S, q, p, region, Subdivision::none, mark(V, r, q, p), v, crossed, at, hook))
      return *l;
  }
}

// walk from a vertex (walk.hpp), telling `hook` (NoTrace: nothing, and no trace code).
template <class H>
Location walk_from(const Subdivision& S, const Point& p, Index qv, std::vector<Index>* crossed, H& hook) {
  const auto& P = S.points();
  if (p == antipode(P[qv])) qv = S.dest(S.first(S.corners(qv)[0].face) + S.corners(qv)[0].k);
  const Point& q = P[qv];
  if (p == q) {
    tell(hook, trace::Event::reach_vertex, {std::size_t(qv)});
    return at_vertex(S, qv);
  }
  return from_vertex(S, q, p, qv, crossed, hook);
}

}  // namespace

Location walk(const Subdivision& S, const Point& p, Index qv, std::vector<Index>* crossed) {
  NoTrace none;
  return walk_from(S, p, qv, crossed, none);
}

Location walk(const Subdivision& S, const Point& p, Index qv, const trace::AnyHook& hook) {
  return walk_from(S, p, qv, nullptr, hook);
}

Location walk(const Subdivision& S, const Point& p, const Point& from, Index face, std::vector<Index>* crossed) {
  if (!crossed)
    if (auto l = visibility_walk(S, p, face)) return *l;
  if (p == from) return {Location::Kind::face, face, 0};
  if (p == antipode(from)) return walk(S, p, S.org(S.first(face)), crossed);
  const Point r = detail::off_line_point(from, p);
  Index v = Subdivision::none;
  NoTrace none;
  if (auto l = through_regions(S, from, p, face, Subdivision::none, mark(from, r, from, p), v, crossed,
                               Subdivision::none, none))
    return *l;
  return from_vertex(S, from, p, v, crossed, none);
}

Location locate_brute(const Subdivision& S, const Point& p) {
  const auto& P = S.points();
  for (Index f = 0; f < S.faces(); ++f) {
    Polygon F;
    for (Index h = S.first(f); h < S.first(f) + S.size(f); ++h) F.push_back(P[S.org(h)]);
    const Sign s = locate(F, p);
    if (s == POSITIVE) return {Location::Kind::face, f, 0};
    if (s == ZERO) {
      for (Index k = 0; k < F.size(); ++k)
        if (F[k] == p) return {Location::Kind::vertex, f, k};
      for (Index k = 0; k < F.size(); ++k)
        if (on_segment(F[k], F[(k + 1) % F.size()], p)) return {Location::Kind::edge, f, k};
    }
  }
  return {};
}

}  // namespace t2
