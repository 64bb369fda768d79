#pragma once
// Exercise 11b: the hidden tests' Delaunay complex and checker (instructors only). No library
// code: the complex is found by brute force in exact rationals from the definition of the
// diagram (chapter 11, section 1, Lemma 1) — every candidate point (the two circumcentres of each
// triple of one side, the two poles of each pair of one side) with the sites nearest to it in
// T²; a candidate in three or more cells is a Voronoi vertex, its sites the polygon, ordered
// around it and fanned from a random corner. The expected answer is then exercise 11's oracle
// for each face, faces of one point merged.
#include <algorithm>
#include <array>
#include <map>
#include <optional>
#include <random>
#include <set>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include <t2/kernel/point.hpp>

#include "oracle.hpp"

namespace ex11btest {

using ex11test::R;
using ex11test::V;
using ex11test::sgn;

/// A canonical representative of the point of T² (a positive multiple): divided by the absolute
/// value of its first non-zero coordinate.
inline V key(const V& v) {
  const R& c = sgn(v[0]) != 0 ? v[0] : sgn(v[1]) != 0 ? v[1] : v[2];
  const R a = sgn(c) > 0 ? c : R(-c);
  return {v[0] / a, v[1] / a, v[2] / a};
}

/// The sites whose cells hold z (z not null): Lemma 1 of chapter 11, in rationals.
inline std::vector<long> owners(const std::vector<t2::Point>& P, const V& z) {
  std::vector<long> best;
  auto keep = [&](std::vector<long>& b, std::optional<R>& top, long i, const R& k) {  // maximise k
    if (!top || k > *top) b.clear(), top = k;
    if (k == *top) b.push_back(i);
  };
  const long n = static_cast<long>(P.size());
  if (sgn(z[0]) != 0) {
    const int sz = sgn(z[0]);
    const R X = z[1] / z[0], Y = z[2] / z[0];
    bool any = false;
    for (const t2::Point& p : P) any = any || ex11test::side(p) == sz;
    std::optional<R> top;
    for (long i = 0; i < n; ++i) {
      const auto A = ex11test::drawn(P[i]);
      const R d2 = (A[0] - X) * (A[0] - X) + (A[1] - Y) * (A[1] - Y);
      if (!any) keep(best, top, i, d2);                      // all beyond infinity: the farthest
      else if (ex11test::side(P[i]) == sz) keep(best, top, i, -d2);  // its side: the nearest
    }
    return best;
  }
  std::vector<long> front, back;
  std::optional<R> tf, tb;
  for (long i = 0; i < n; ++i) {  // the sweep rule: front extreme along u, back along -u
    const auto A = ex11test::drawn(P[i]);
    const R k = z[1] * A[0] + z[2] * A[1];
    if (ex11test::side(P[i]) > 0) keep(front, tf, i, k);
    else keep(back, tb, i, -k);
  }
  front.insert(front.end(), back.begin(), back.end());
  return front;
}

inline bool same(const V& a, const V& b) { return key(a) == key(b); }

inline std::optional<V> vertex_of(const std::vector<t2::Point>& P, long a, long b, long c) {
  return ex11test::vertex(P[a], P[b], P[c]);
}

/// The Delaunay complex of P (proper sites), flat, each polygon fanned from a random corner and
/// the faces shuffled; "" in `error` when all went well. A polygon at a proper vertex is ordered
/// by angle around the drawn centre; one on Ω by trying the cyclic orders until every triple
/// of it has the vertex by exercise 11's formula (the order the chapter's complex has).
inline std::vector<long> brute_complex(const std::vector<t2::Point>& P, std::mt19937_64& g, std::string& error) {
  const long n = static_cast<long>(P.size());
  std::map<V, std::vector<long>> found;  // key of the vertex -> its owners
  auto consider = [&](const V& z) {
    const V k = key(z);
    if (found.count(k)) return;
    std::vector<long> o = owners(P, z);
    if (o.size() >= 3) found.emplace(k, std::move(o));
  };
  for (long i = 0; i < n; ++i)
    for (long j = i + 1; j < n; ++j) {
      if (ex11test::side(P[i]) != ex11test::side(P[j])) continue;
      const auto A = ex11test::drawn(P[i]), B = ex11test::drawn(P[j]);
      consider(V{R(0), A[1] - B[1], B[0] - A[0]});
      consider(V{R(0), B[1] - A[1], A[0] - B[0]});
      for (long k = j + 1; k < n; ++k) {
        if (ex11test::side(P[k]) != ex11test::side(P[i])) continue;
        for (const auto& t : {std::array<long, 3>{i, j, k}, std::array<long, 3>{i, k, j}}) {
          const auto z = vertex_of(P, t[0], t[1], t[2]);
          if (z && sgn((*z)[0]) != 0) consider(*z);
        }
      }
    }
  std::vector<std::array<long, 3>> faces;
  std::set<std::pair<long, long>> sides;
  for (auto& [z, o] : found) {
    if (sgn(z[0]) != 0) {  // around the drawn centre, by angle
      const R X = z[1] / z[0], Y = z[2] / z[0];
      auto half = [&](long i) {
        const auto A = ex11test::drawn(P[i]);
        return sgn(A[1] - Y) > 0 || (sgn(A[1] - Y) == 0 && sgn(A[0] - X) > 0) ? 0 : 1;
      };
      std::sort(o.begin(), o.end(), [&](long i, long j) {
        if (half(i) != half(j)) return half(i) < half(j);
        const auto A = ex11test::drawn(P[i]), B = ex11test::drawn(P[j]);
        return sgn((A[0] - X) * (B[1] - Y) - (A[1] - Y) * (B[0] - X)) > 0;
      });
    } else {  // on Ω: the cyclic order in which every triple has the vertex z (few sites)
      std::sort(o.begin() + 1, o.end());
      auto all_fit = [&] {
        for (std::size_t i = 0; i < o.size(); ++i)
          for (std::size_t j = i + 1; j < o.size(); ++j)
            for (std::size_t l = j + 1; l < o.size(); ++l) {
              const auto v = vertex_of(P, o[i], o[j], o[l]);
              if (!v || !same(*v, z)) return false;
            }
        return true;
      };
      while (!all_fit())
        if (!std::next_permutation(o.begin() + 1, o.end())) {
          error = "bad test input: no order of a polygon on Ω fits its vertex";
          return {};
        }
    }
    auto fits = [&] { const auto v = vertex_of(P, o[0], o[1], o[2]); return v && same(*v, z); };
    if (!fits()) std::reverse(o.begin(), o.end());
    if (!fits()) {
      error = "bad test input: no order of a polygon fits its vertex";
      return {};
    }
    // Fan from a random corner whose diagonals no other fan holds (a side in one face only).
    bool placed = false;
    for (int attempt = 0; attempt < 200 && !placed; ++attempt) {
      std::rotate(o.begin(), o.begin() + static_cast<long>(g() % o.size()), o.end());
      std::vector<std::array<long, 3>> fan;
      for (std::size_t i = 1; i + 1 < o.size(); ++i) fan.push_back({o[0], o[i], o[i + 1]});
      placed = std::none_of(fan.begin(), fan.end(), [&](const std::array<long, 3>& f) {
        for (int i = 0; i < 3; ++i)
          if (sides.count({f[i], f[(i + 1) % 3]})) return true;
        return false;
      });
      if (!placed) continue;
      for (const auto& f : fan)
        for (int i = 0; i < 3; ++i) sides.insert({f[i], f[(i + 1) % 3]});
      faces.insert(faces.end(), fan.begin(), fan.end());
    }
    if (!placed) {
      error = "bad test input: no fan of a polygon fits the others";
      return {};
    }
  }
  std::shuffle(faces.begin(), faces.end(), g);
  std::vector<long> F;
  for (auto& f : faces) {
    std::rotate(f.begin(), f.begin() + static_cast<long>(g() % 3), f.end());
    F.insert(F.end(), f.begin(), f.end());
  }
  if (faces.size() != static_cast<std::size_t>(2 * n - 4))
    error = "bad test input: " + std::to_string(faces.size()) + " faces, not 2n - 4";
  return F;
}

/// Half-edge 3f + i is the side F[3f + i] -> F[3f + (i + 1) % 3]; its twin, or -1; empty when a
/// side appears twice.
inline std::vector<long> twins(const std::vector<long>& F) {
  std::map<std::pair<long, long>, long> at;
  auto next = [&](long h) { return F[h - h % 3 + (h + 1) % 3]; };
  for (long h = 0; h < static_cast<long>(F.size()); ++h)
    if (!at.emplace(std::pair{F[h], next(h)}, h).second) return {};  // a side twice: not a complex
  std::vector<long> t(F.size(), -1);
  for (long h = 0; h < static_cast<long>(F.size()); ++h) {
    const auto it = at.find({next(h), F[h]});
    if (it != at.end()) t[h] = it->second;
  }
  return t;
}

using Edge = std::array<long, 4>;

/// (a, b, s, t) as (b, a, t, s) when s > t: one writing of each edge.
inline Edge canonical(Edge e) { return e[2] < e[3] ? e : Edge{e[1], e[0], e[3], e[2]}; }

/// "" when (vertices, edges) is the dual of the complex F of P, else what is wrong.
inline std::string check(const std::vector<t2::Point>& P, const std::vector<long>& F,
                         const std::vector<t2::ExactPoint>& vertices, const std::vector<long>& edges) {
  const long m = static_cast<long>(F.size() / 3);
  const std::vector<long> t = twins(F);
  if (t.size() != F.size()) return "bad test input: a side in two faces";
  std::map<V, long> number;  // key -> expected vertex number
  std::vector<long> first, klass(m);
  for (long f = 0; f < m; ++f) {
    const auto z = vertex_of(P, F[3 * f], F[3 * f + 1], F[3 * f + 2]);
    if (!z) return "bad test input: a face without a vertex";
    const auto [it, fresh] = number.emplace(key(*z), static_cast<long>(first.size()));
    if (fresh) first.push_back(f);
    klass[f] = it->second;
  }
  if (vertices.size() != first.size())
    return std::to_string(vertices.size()) + " vertices, expected " + std::to_string(first.size()) +
           " (one per distinct point, faces with the same vertex merged)";
  for (std::size_t k = 0; k < first.size(); ++k) {
    const long f = first[k];
    const std::string e = ex11test::check(P[F[3 * f]], P[F[3 * f + 1]], P[F[3 * f + 2]], vertices[k]);
    if (!e.empty()) return "vertex " + std::to_string(k) + " (of face " + std::to_string(f) + "): " + e;
  }
  std::vector<Edge> want, got;
  for (long h = 0; h < 3 * m; ++h) {
    if (t[h] < 0) return "bad test input: a side without a twin";
    if (t[h] > h && klass[h / 3] != klass[t[h] / 3])
      want.push_back(canonical({klass[h / 3], klass[t[h] / 3], F[h], F[h - h % 3 + (h + 1) % 3]}));
  }
  if (edges.size() % 4 != 0) return "the edges are not quadruples (a, b, s, t)";
  for (std::size_t i = 0; i < edges.size(); i += 4)
    got.push_back(canonical({edges[i], edges[i + 1], edges[i + 2], edges[i + 3]}));
  std::sort(want.begin(), want.end());
  std::sort(got.begin(), got.end());
  if (got == want) return "";
  auto show = [](const Edge& e) {
    return "(" + std::to_string(e[0]) + ", " + std::to_string(e[1]) + ", " + std::to_string(e[2]) + ", " +
           std::to_string(e[3]) + ")";
  };
  for (const Edge& e : got)
    if (!std::binary_search(want.begin(), want.end(), e)) return "edge " + show(e) + " is not a Voronoi edge";
  for (const Edge& e : want)
    if (!std::binary_search(got.begin(), got.end(), e)) return "the Voronoi edge " + show(e) + " is missing";
  return std::to_string(got.size()) + " edges, expected " + std::to_string(want.size()) + " (each edge once)";
}

}  // namespace ex11btest
