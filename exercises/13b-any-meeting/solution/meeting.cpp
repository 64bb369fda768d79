// Exercise 13b, reference solution: the sweep of chapter 13, section 3, stopped at the first
// meeting it finds (Shamos and Hoey's test), run in each of the six faces of the cube around
// T². A face, say w ≥ |x|, w ≥ |y|, is a closed convex piece of the sphere with w > 0, so its
// chart (x/w, y/w) is a bounded square where every segment is a straight segment; a segment
// of T² meets a face in one piece (both are convex, the segment shorter than half a circle),
// and two segments meet iff their pieces meet in some face. Every question is the sign of an
// integer polynomial in exact coordinates, so nothing is rounded.
#include "meeting.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <set>

#include <t2/kernel/number.hpp>

namespace ex13b {

namespace {

using t2::Integer;
using V = std::array<Integer, 3>;  // (w, x, y) in T², (W, U, V) in a face's chart with W > 0

// A chart point, and a copy of it in machine integers when every coordinate is below 2³¹ in
// absolute value: then a 3 × 3 determinant (six products of three, each below 2⁹³) and the
// products of two in `lex` are exact in __int128, and no big integer is needed.
struct C {
  V v;
  bool small = false;
  long s[3] = {0, 0, 0};
};

C make(V v) {
  C c;
  c.small = true;
  for (int i = 0; i < 3; ++i) c.small = c.small && abs(v[i]) < (Integer(1) << 31);
  if (c.small)
    for (int i = 0; i < 3; ++i) c.s[i] = v[i].get_si();
  c.v = std::move(v);
  return c;
}

struct Piece {
  long seg;  // the segment it is a piece of
  C l, r;    // its ends in the chart, l ≤ r in the sweep order
};

// Scratch integers, so that the predicates below allocate nothing once they have grown.
mpz_ptr scratch(int i) {
  static thread_local Integer s[3];
  return s[i].get_mpz_t();
}

// Orientation of three chart points (W > 0): positive when r is left of p → q. The 3 × 3
// determinant, expanded along p.
int orient(const C& pc, const C& qc, const C& rc) {
  if (pc.small && qc.small && rc.small) {
    using I = __int128;
    const long *p = pc.s, *q = qc.s, *r = rc.s;
    const I d = I(p[0]) * (I(q[1]) * r[2] - I(q[2]) * r[1]) - I(p[1]) * (I(q[0]) * r[2] - I(q[2]) * r[0]) +
                I(p[2]) * (I(q[0]) * r[1] - I(q[1]) * r[0]);
    return (d > 0) - (d < 0);
  }
  const V &p = pc.v, &q = qc.v, &r = rc.v;
  mpz_ptr t = scratch(0), d = scratch(1);
  auto z = [](const Integer& v) { return v.get_mpz_t(); };
  mpz_mul(t, z(q[1]), z(r[2]));
  mpz_submul(t, z(q[2]), z(r[1]));
  mpz_mul(d, z(p[0]), t);
  mpz_mul(t, z(q[0]), z(r[2]));
  mpz_submul(t, z(q[2]), z(r[0]));
  mpz_submul(d, z(p[1]), t);
  mpz_mul(t, z(q[0]), z(r[1]));
  mpz_submul(t, z(q[1]), z(r[0]));
  mpz_addmul(d, z(p[2]), t);
  return mpz_sgn(d);
}

// The sweep order of chart points: by U/W, then V/W (W > 0, so cross-multiplying keeps signs;
// points of one weight, as the ends of most whole segments are, compare without products).
int lex(const C& pc, const C& qc) {
  if (pc.small && qc.small) {
    const long *p = pc.s, *q = qc.s;
    for (int i = 1; i < 3; ++i) {
      const __int128 d = __int128(p[i]) * q[0] - __int128(q[i]) * p[0];
      if (d != 0) return d > 0 ? 1 : -1;
    }
    return 0;
  }
  const V &p = pc.v, &q = qc.v;
  auto z = [](const Integer& v) { return v.get_mpz_t(); };
  auto less = [&](int i) {
    if (mpz_cmp(z(p[0]), z(q[0])) == 0) {
      const int c = mpz_cmp(z(p[i]), z(q[i]));
      return (c > 0) - (c < 0);
    }
    mpz_ptr t = scratch(2);
    mpz_mul(t, z(p[i]), z(q[0]));
    mpz_submul(t, z(q[i]), z(p[0]));
    return mpz_sgn(t);
  };
  const int s = less(1);
  return s != 0 ? s : less(2);
}

bool within(const C& p, const Piece& s) { return lex(s.l, p) <= 0 && lex(p, s.r) <= 0; }

// Do two closed pieces of one chart meet? A proper crossing, or an end of one on the other
// (collinear pieces and one-point pieces included).
bool meet(const Piece& s, const Piece& t) {
  const int d1 = orient(s.l, s.r, t.l), d2 = orient(s.l, s.r, t.r);
  const int d3 = orient(t.l, t.r, s.l), d4 = orient(t.l, t.r, s.r);
  if (d1 * d2 < 0 && d3 * d4 < 0) return true;
  return (d1 == 0 && within(t.l, s)) || (d2 == 0 && within(t.r, s)) || (d3 == 0 && within(s.l, t)) ||
         (d4 == 0 && within(s.r, t));
}

// Is the point p (doubles, exact comparisons) on the right side of the face constraint
// σ·p[k] ≥ e·p[j]?
double coord(const t2::Point& p, int i) { return i == 0 ? p.w() : i == 1 ? p.x() : p.y(); }

// The piece of the segment ab (exact a, b; doubles pa, pb) in face f (axis k = f / 2, sign
// σ = ±1): the points (1 − t)a + tb, t ∈ [0, 1], with σ·p[k] ≥ |p[j]| for j ≠ k. Each
// constraint is linear in t, so the piece is an interval [lo, hi] of t.
bool piece(const t2::Point& pa, const t2::Point& pb, const V& a, const V& b, int f, Piece& out) {
  const int k = f / 2, sg = f % 2 ? -1 : 1;
  Integer lo_n = 0, lo_d = 1, hi_n = 1, hi_d = 1;
  bool cut = false;
  for (int j = 0; j < 3; ++j) {
    if (j == k) continue;
    for (const int e : {1, -1}) {
      const bool ina = sg * coord(pa, k) >= e * coord(pa, j), inb = sg * coord(pb, k) >= e * coord(pb, j);
      if (ina && inb) continue;
      if (!ina && !inb) return false;
      cut = true;
      const Integer A = sg * a[k] - e * a[j], B = sg * b[k] - e * b[j];
      Integer tn = A, td = A - B;  // t = A / (A − B), where the constraint changes sign
      if (td < 0) tn = -tn, td = -td;
      if (ina) {  // holds up to t
        if (tn * hi_d < hi_n * td) hi_n = tn, hi_d = td;
      } else if (tn * lo_d > lo_n * td) {  // holds from t on
        lo_n = tn, lo_d = td;
      }
    }
  }
  if (lo_n * hi_d > hi_n * lo_d) return false;
  auto chart = [&](const V& p) { return V{sg * p[k], p[(k + 1) % 3], p[(k + 2) % 3]}; };
  auto at = [&](const Integer& n, const Integer& d) {
    return V{(d - n) * a[0] + n * b[0], (d - n) * a[1] + n * b[1], (d - n) * a[2] + n * b[2]};
  };
  C l = make(cut ? chart(at(lo_n, lo_d)) : chart(a)), r = make(cut ? chart(at(hi_n, hi_d)) : chart(b));
  if (lex(l, r) > 0) std::swap(l, r);
  out.l = std::move(l), out.r = std::move(r);
  return true;
}

// The status order for the sweep: is piece i below piece j just right of the current event?
// One of them is being inserted at its left end e; the other, in the status, is compared with
// e by one orientation. e on it means the two meet: recorded, and the sweep stops.
struct Below {
  const std::vector<Piece>* P;
  const int* inserting;
  long* hit;
  bool operator()(int i, int j) const {
    const bool i_new = i == *inserting;
    const Piece &n = (*P)[i_new ? i : j], &o = (*P)[i_new ? j : i];
    const int s = orient(o.l, o.r, n.l);
    if (s == 0) {
      hit[0] = std::min(n.seg, o.seg), hit[1] = std::max(n.seg, o.seg);
      return i < j;
    }
    return i_new ? s < 0 : s > 0;
  }
};

std::vector<long> sweep(const std::vector<Piece>& P) {
  std::vector<std::pair<int, bool>> ev;  // (piece, insertion?)
  for (int i = 0; i < int(P.size()); ++i) ev.push_back({i, true}), ev.push_back({i, false});
  std::sort(ev.begin(), ev.end(), [&](const auto& x, const auto& y) {
    const int s = lex(x.second ? P[x.first].l : P[x.first].r, y.second ? P[y.first].l : P[y.first].r);
    if (s != 0) return s < 0;
    return x.second && !y.second;  // at one point: insertions first, so shared ends meet
  });
  int inserting = -1;
  long hit[2] = {-1, -1};
  std::set<int, Below> status(Below{&P, &inserting, hit});
  std::vector<std::set<int, Below>::iterator> where(P.size());
  auto pair = [&](int i, int j) { return std::vector<long>{std::min(P[i].seg, P[j].seg), std::max(P[i].seg, P[j].seg)}; };
  for (const auto& [i, insertion] : ev) {
    if (insertion) {
      inserting = i;
      const auto it = status.insert(i).first;
      if (hit[0] >= 0) return {hit[0], hit[1]};
      where[i] = it;
      if (it != status.begin() && meet(P[*std::prev(it)], P[i])) return pair(*std::prev(it), i);
      if (std::next(it) != status.end() && meet(P[*std::next(it)], P[i])) return pair(*std::next(it), i);
    } else {
      const auto it = where[i], next = std::next(it);
      if (it != status.begin() && next != status.end() && meet(P[*std::prev(it)], P[*next]))
        return pair(*std::prev(it), *next);
      status.erase(it);
    }
  }
  return {};
}

V vec(const t2::Point& p) {
  const t2::ExactPoint e = t2::to_exact(p);
  return {e.w(), e.x(), e.y()};
}

}  // namespace

std::vector<long> meeting_pair(const std::vector<t2::Point>& a, const std::vector<t2::Point>& b) {
  std::vector<V> ea, eb;
  for (std::size_t i = 0; i < a.size(); ++i) ea.push_back(vec(a[i])), eb.push_back(vec(b[i]));
  for (int f = 0; f < 6; ++f) {
    std::vector<Piece> P;
    Piece p;
    for (std::size_t i = 0; i < a.size(); ++i)
      if (piece(a[i], b[i], ea[i], eb[i], f, p)) p.seg = long(i), P.push_back(p);
    if (auto r = sweep(P); !r.empty()) return r;
  }
  return {};
}

}  // namespace ex13b
