// The structural operations of t2::Triangulation (see triangulation.hpp for the invariants).
#include "t2/triangulation/triangulation.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>
#include <unordered_map>
#include <vector>

#include "t2/kernel/lexicographic.hpp"
#include "t2/kernel/orient.hpp"
#include "t2/triangulation/antipodal_edge.hpp"
#include "t2/triangulation/spatial_sort.hpp"

namespace t2 {

void Triangulation::make_triangle(Index a, Index b, Index c, std::size_t reserve) {
  v_.clear();
  n_.clear();
  v_.reserve(6 * std::max<std::size_t>(reserve, 3));
  n_.reserve(6 * std::max<std::size_t>(reserve, 3));
  for (int k = 0; k < 4; ++k) add_triangle();
  // t0 = (a, b, c); across its edge opposite slot m lies the infinite triangle m + 1.
  set(0, a, b, c);
  set(1, c, b, infinite);  // outside b → c (opposite a)
  set(2, a, c, infinite);  // outside c → a (opposite b)
  set(3, b, a, infinite);  // outside a → b (opposite c)
  link(0, 3 * 1 + 2);
  link(1, 3 * 2 + 2);
  link(2, 3 * 3 + 2);
  // infinite triangles share the edges (v, v∞): (c, b, ∞) and (b, a, ∞) share b∞, etc.
  link(3 * 1 + 0, 3 * 3 + 1);  // edge (b, ∞): opposite c in t1, opposite a in t3
  link(3 * 1 + 1, 3 * 2 + 0);  // edge (∞, c): opposite b in t1, opposite a in t2
  link(3 * 2 + 1, 3 * 3 + 0);  // edge (a, ∞)... opposite c in t2, opposite b in t3
  dimension_ = 2;
  link_.assign(points_.size() + 1, none);
  set_link(a, 0);
  set_link(b, 0);
  set_link(c, 0);
  set_link(infinite, 1);
}

void Triangulation::make_fan(Index p, const Index* ring, const Index* ext, const Index* tri, int k) {
  for (int m = 0; m < k; ++m) {
    set(tri[m], p, ring[m], ring[(m + 1) % k]);
    link(3 * tri[m], ext[m]);
    set_link(ring[m], tri[m]);  // ring[m] may have lost the triangle its link named
  }
  set_link(p, tri[0]);
  for (int m = 0; m < k; ++m) link(3 * tri[m] + 1, 3 * tri[(m + 1) % k] + 2);
}

//> insert-in-face
void Triangulation::insert_in_face(Index t, Index p) {
  const Index ring[3] = {v_[3 * t], v_[3 * t + 1], v_[3 * t + 2]};
  // outside a→b, b→c, c→a
  const Index ext[3] = {n_[3 * t + 2], n_[3 * t], n_[3 * t + 1]};
  const Index t1 = add_triangle(), t2 = add_triangle();
  const Index tri[3] = {t, t1, t2};
  make_fan(p, ring, ext, tri, 3);
}
//< insert-in-face

void Triangulation::insert_on_edge(Index t, int i, Index p) {
  const Index e = n_[3 * t + i], u = e / 3;
  const int j = static_cast<int>(e % 3);
  const Index a = v_[3 * t + i], q = v_[3 * t + next(i)], r = v_[3 * t + prev(i)], d = v_[3 * u + j];
  // Around p counter-clockwise: q, d, r, a (u = (d, r, q) lies beyond q → r).
  const Index ring[4] = {q, d, r, a};
  const Index ext[4] = {n_[3 * u + next(j)], n_[3 * u + prev(j)], n_[3 * t + next(i)], n_[3 * t + prev(i)]};
  const Index t2 = add_triangle(), t3 = add_triangle();
  const Index tri[4] = {u, t2, t3, t};
  make_fan(p, ring, ext, tri, 4);
}

//> flip
void Triangulation::flip(Index t, int i) {
  const Index e = n_[3 * t + i], u = e / 3;
  const int j = static_cast<int>(e % 3);
  const Index p = v_[3 * t + i], q = v_[3 * t + next(i)], r = v_[3 * t + prev(i)],
              d = v_[3 * u + j];
  const Index qd = n_[3 * u + next(j)], dr = n_[3 * u + prev(j)];  // beyond q→d and d→r
  const Index rp = n_[3 * t + next(i)], pq = n_[3 * t + prev(i)];  // beyond r→p and p→q
  set(t, p, q, d);
  set(u, p, d, r);
  link(3 * t, qd);
  link(3 * t + 2, pq);
  link(3 * u, dr);
  link(3 * u + 1, rp);
  link(3 * t + 1, 3 * u + 2);  // the new edge p–d
  set_link(q, t);  // q left u, r left t; p stays in t, d in u
  set_link(r, u);
}
//< flip

void Triangulation::assemble(const std::vector<std::array<Index, 3>>& triangles) {
  v_.assign(3 * triangles.size(), 0);
  n_.assign(3 * triangles.size(), none);
  std::unordered_map<std::uint64_t, Index> edges;  // directed edge u → v -> its half-edge
  edges.reserve(3 * triangles.size());
  auto key = [](Index u, Index v) { return (std::uint64_t(u) << 32) | v; };
  for (Index t = 0; t < triangles.size(); ++t) {
    set(t, triangles[t][0], triangles[t][1], triangles[t][2]);
    for (int i = 0; i < 3; ++i)  // the half-edge 3t + i is the edge vertex(i+1) → vertex(i+2)
      if (!edges.emplace(key(triangles[t][next(i)], triangles[t][prev(i)]), 3 * t + i).second)
        throw std::logic_error("Triangulation::assemble: a directed edge occurs twice");
  }
  for (Index t = 0; t < triangles.size(); ++t)
    for (int i = 0; i < 3; ++i) {
      const auto it = edges.find(key(triangles[t][prev(i)], triangles[t][next(i)]));
      if (it == edges.end()) throw std::logic_error("Triangulation::assemble: an edge has no opposite");
      n_[3 * t + i] = it->second;
    }
  dimension_ = 2;
  relink();
}

void Triangulation::relink() {
  std::size_t top = points_.size();  // the points may come later (divide.hpp assigns first)
  for (Index v : v_)
    if (v != infinite && v >= top) top = std::size_t(v) + 1;
  link_.assign(top + 1, none);
  for (Index e = 0; e < v_.size(); ++e) link_[v_[e] + 1] = e / 3;
}

void Triangulation::rename_vertex(Index t, Index from, Index to) {
  const Index start = t;
  do {
    const int k = slot(t, from);
    v_[3 * t + k] = to;
    t = n_[3 * t + next(k)] / 3;
  } while (t != start);
  set_link(from, none);
  set_link(to, start);
  for (AntipodalEdge& e : antipodal_)
    for (Index* x : {&e.z, &e.nz, &e.u, &e.w})
      if (*x == from) *x = to;
}

void Triangulation::renumber_indices(const std::vector<Index>& order) {
  for (Index& v : v_)
    if (v != infinite) v = order[v];
  for (auto& [d, k] : duplicates_) d = order[d], k = order[k];
  for (AntipodalEdge& e : antipodal_)
    for (Index* x : {&e.z, &e.nz, &e.u, &e.w}) *x = order[*x];
}

void Triangulation::renumber_link(const std::vector<Index>& order, std::size_t count) {
  if (link_.empty()) return;
  std::vector<Index> moved(count + 1, none);  // vertex k moves to order[k]
  moved[0] = link_[0];
  const std::size_t n = std::min(order.size(), link_.size() - 1);
  for (std::size_t k = 0; k < n; ++k) moved[std::size_t(order[k]) + 1] = link_[k + 1];
  link_.swap(moved);
}

void Triangulation::renumber(std::vector<Index> order, std::span<const Point> input) {
  renumber_indices(order);
  // Free the sorted copy and the order before the copy of the input (`v = {}` would keep the
  // capacity). When the order is a permutation of all the points, the link moves in place,
  // through the cycles of the order (which it uses up); otherwise (divide.hpp's distinct points)
  // through a second array.
  std::vector<Point>().swap(points_);
  if (order.size() != input.size()) {
    renumber_link(order, input.size());
  } else if (!link_.empty()) {
    link_.resize(input.size() + 1, none);
    for (Index k = 0; k < order.size(); ++k)
      while (order[k] != k) {  // the link at k + 1 goes to order[k] + 1: swap, then follow
        const Index j = order[k];
        std::swap(link_[std::size_t(k) + 1], link_[std::size_t(j) + 1]);
        std::swap(order[k], order[j]);
      }
  }
  std::vector<Index>().swap(order);
  points_.assign(input.begin(), input.end());
}

void Triangulation::renumber(std::vector<Index> order) {
  renumber_indices(order);
  renumber_link(order, points_.size());
  unpermute(points_, order);  // order is scratch from here on
}

void Triangulation::finish() {
  if (duplicates_.empty()) return;
  // kept[d] = the index d was merged into (a flat array: the grid benchmark has ~10⁵ duplicates).
  Index top = 0;
  for (auto [d, k] : duplicates_) top = std::max({top, d, k});
  std::vector<Index> kept(std::size_t(top) + 1, none);
  for (auto [d, k] : duplicates_) kept[d] = k;
  for (auto& [d, k] : duplicates_)
    while (kept[k] != none) k = kept[k];
  std::sort(duplicates_.begin(), duplicates_.end());
}

std::vector<std::array<Triangulation::Index, 3>> Triangulation::finite_triangles() const {
  std::vector<std::array<Index, 3>> out;
  out.reserve(size());
  for (Index t = 0; t < size(); ++t) {
    if (is_infinite(t)) continue;
    const Index* v = &v_[3 * t];
    const int m = v[0] < v[1] ? (v[0] < v[2] ? 0 : 2) : (v[1] < v[2] ? 1 : 2);
    out.push_back({v[m], v[next(m)], v[prev(m)]});
  }
  return out;
}

std::vector<std::pair<Triangulation::Index, Triangulation::Index>> Triangulation::hull_edges() const {
  std::vector<std::pair<Index, Index>> out;
  for (Index t = 0; t < size(); ++t) {
    const int k = slot(t, infinite);
    if (k >= 0) out.emplace_back(v_[3 * t + prev(k)], v_[3 * t + next(k)]);
  }
  std::sort(out.begin(), out.end());
  return out;
}

std::string Triangulation::validate() const {
  if (v_.size() != n_.size() || v_.size() % 3 != 0) return "arrays of different or non-multiple-of-3 sizes";
  if (dimension_ < 2) return v_.empty() ? "" : "triangles in dimension < 2";
  const Index np = static_cast<Index>(points_.size());
  const bool has_infinite = std::find(v_.begin(), v_.end(), infinite) != v_.end();
  std::vector<Index> count(points_.size() + 1, 0);  // last: v∞
  for (Index e = 0; e < v_.size(); ++e) {
    const Index v = v_[e], t = e / 3;
    if (v != infinite && v >= np) return "vertex index out of range in triangle " + std::to_string(t);
    ++count[v == infinite ? np : v];
    const Index f = n_[e];
    if (f >= n_.size() || n_[f] != e || f / 3 == t) return "twin is not an involution at half-edge " + std::to_string(e);
    const int i = static_cast<int>(e % 3), j = static_cast<int>(f % 3);
    const Index u = f / 3;
    if (v_[3 * t + next(i)] != v_[3 * u + prev(j)] || v_[3 * t + prev(i)] != v_[3 * u + next(j)])
      return "twin edges with different endpoints at half-edge " + std::to_string(e);
    if (i == 0 && !is_infinite(t)) {
      const Point &a = points_[v_[e]], &b = points_[v_[e + 1]], &c = points_[v_[e + 2]];
      const Sign o = orient(a, b, c);
      const bool antipodal = a == antipode(b) || b == antipode(c) || c == antipode(a);
      if (o == NEGATIVE) return "triangle " + std::to_string(t) + " is not counter-clockwise";
      // a flat face: no v∞ (no hull), its vertices in an open half of their great circle
      if (o == ZERO && !antipodal &&
          (has_infinite || !(inside_arc(a, c, b) || inside_arc(b, a, c) || inside_arc(c, b, a))))
        return "triangle " + std::to_string(t) + " is flat (orient 0) " +
               (has_infinite ? "while v∞ is a vertex" : "with its vertices in no open half of their great circle");
    }
  }
  if (count[np] == 0 && std::all_of(points_.begin(), points_.end(), [](const Point& p) { return p.w() > 0; }))
    return "v∞ is not a vertex";  // front points always have a hull
  // Each vertex's triangles form one cycle (its star), so no vertex is pinched.
  std::vector<Index> first(points_.size() + 1, none);
  for (Index e = 0; e < v_.size(); ++e) {
    const Index v = v_[e] == infinite ? np : v_[e];
    if (first[v] == none) first[v] = e / 3;
  }
  Index vertices = 0;
  for (Index v = 0; v <= np; ++v) {
    if (count[v] == 0) continue;
    ++vertices;
    const Index id = v == np ? infinite : v;
    Index t = first[v], steps = 0;
    do {
      t = n_[3 * t + next(slot(t, id))] / 3;
      ++steps;
    } while (t != first[v] && steps <= count[v]);
    if (steps != count[v]) return "the triangles around vertex " + std::to_string(v) + " are not one cycle";
  }
  if (size() != 2 * std::size_t(vertices) - 4) return "Euler's formula fails: T != 2V - 4";
  // Invariant 5: the link names a triangle of each vertex, and `none` for the other points.
  if (link_.size() != points_.size() + 1) return "the vertex link has the wrong size";
  for (Index v = 0; v <= np; ++v) {
    const Index id = v == np ? infinite : v, f = face_of(id);
    if (count[v] == 0 ? f != none : f >= size() || slot(f, id) < 0)
      return "the link of vertex " + std::to_string(v) + " does not name one of its triangles";
  }
  if (count[np] == 0 && size() == 0) return "no triangle in dimension 2";
  // Invariant 6: one record per antipodal edge, and no record of an edge that is not one.
  std::vector<int> records(antipodal_.size(), 0);
  for (Index h = 0; h < v_.size(); ++h) {
    const Index a = org(h), b = dest(h);
    if (h > n_[h] || a == infinite || b == infinite || !(points_[a] == antipode(points_[b]))) continue;
    int found = 0;
    for (std::size_t k = 0; k < antipodal_.size(); ++k) {
      const AntipodalEdge& e = antipodal_[k];
      if ((e.z == a && e.nz == b) || (e.z == b && e.nz == a)) ++found, ++records[k];
    }
    if (found != 1)
      return "the antipodal edge " + std::to_string(a) + "-" + std::to_string(b) + " has " + std::to_string(found) +
             " records";
  }
  for (std::size_t k = 0; k < records.size(); ++k)
    if (records[k] != 1) return "the antipodal-edge record " + std::to_string(k) + " names no edge";
  // No two vertices at the same point.
  std::vector<Index> used;
  for (Index v = 0; v < np; ++v)
    if (count[v] != 0) used.push_back(v);
  std::sort(used.begin(), used.end(),
            [&](Index a, Index b) { return compare_lexicographic(points_[a], points_[b]) == NEGATIVE; });
  for (std::size_t k = 1; k < used.size(); ++k)
    if (compare_lexicographic(points_[used[k - 1]], points_[used[k]]) == ZERO)
      return "vertices " + std::to_string(used[k - 1]) + " and " + std::to_string(used[k]) + " are the same point";
  return "";
}

}  // namespace t2
