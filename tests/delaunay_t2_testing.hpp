#pragma once
// The T² Delaunay certificates shared by test_delaunay_t2 and test_delaunay_omega: random points
// on both sides, the O(n⁴) brute force with the exact predicate in_face_disk (the definition),
// and the exact certificates of a T² Delaunay triangulation.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <random>
#include <vector>

#include "delaunay_certificates.hpp"
#include "t2/triangulation/delaunay.hpp"
#include "t2/triangulation/face_disk.hpp"

namespace t2::testing {

using Index = Triangulation::Index;  ///< vertex indices

inline bool flat(const Point& a, const Point& b, const Point& c) { return orient(a, b, c) == ZERO; }

/// n random points in [-1, 1)², each behind with probability `back` (drawn at the same place).
inline std::vector<Point> random_sides(std::size_t n, double back, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(-1, 1), coin(0, 1);
  std::vector<Point> out;
  for (std::size_t k = 0; k < n; ++k) {
    const double x = u(rng), y = u(rng);
    out.push_back(coin(rng) < back ? Point(-1, -x, -y) : Point::cartesian(x, y));
  }
  return out;
}

/// The counter-clockwise triples of distinct points whose disk (in_face_disk) holds no point:
/// the faces of the Delaunay triangulation by definition, in O(n⁴).
inline std::vector<Tri> brute_force(const std::vector<Point>& p) {
  std::vector<Tri> out;
  const Index n = static_cast<Index>(p.size());
  for (Index a = 0; a < n; ++a)
    for (Index b = 0; b < n; ++b)
      for (Index c = 0; c < n; ++c) {
        if (!(a < b && a < c) || b == c || orient(p[a], p[b], p[c]) != POSITIVE) continue;
        bool empty = true;
        for (Index d = 0; d < n && empty; ++d)
          if (d != a && d != b && d != c && in_face_disk(p[a], p[b], p[c], p[d]) == POSITIVE) empty = false;
        if (empty) out.push_back({a, b, c});
      }
  std::sort(out.begin(), out.end());
  return out;
}

/// The finite faces that turn counter-clockwise (the flat antipodal faces left out).
inline std::vector<Tri> proper_faces(const Triangulation& tr) {
  std::vector<Tri> out;
  for (const Tri& t : triangle_set(tr))
    if (!flat(tr.point(t[0]), tr.point(t[1]), tr.point(t[2]))) out.push_back(t);
  return out;
}

/// The certificates of the file comment; `samples` random points for the tiling count.
inline void expect_t2_delaunay(const Triangulation& tr, std::size_t samples = 200) {
  ASSERT_EQ(tr.validate(), "");
  ASSERT_EQ(tr.dimension(), 2);
  const auto& p = tr.points();
  std::vector<char> vertex(p.size(), 0), dropped(p.size(), 0);
  for (const Tri& t : tr.finite_triangles())
    for (Index v : t) vertex[v] = 1;
  for (auto [d, k] : tr.duplicates()) {
    EXPECT_TRUE(p[d] == p[k]);
    EXPECT_LT(k, d);
    dropped[d] = 1;
  }
  for (std::size_t v = 0; v < p.size(); ++v) EXPECT_NE(vertex[v] != 0, dropped[v] != 0) << "point " << v;
  bool any_flat = false;
  for (const Tri& t : tr.finite_triangles()) {
    const bool is_flat = flat(p[t[0]], p[t[1]], p[t[2]]);
    any_flat = any_flat || is_flat;
    if (is_flat && (p[t[0]].w() == 0 || p[t[1]].w() == 0 || p[t[2]].w() == 0)) continue;  // no disk
    for (std::size_t d = 0; d < p.size(); ++d)
      ASSERT_NE(in_face_disk(p[t[0]], p[t[1]], p[t[2]], p[d]), POSITIVE)
          << "point " << d << " inside the disk of " << t[0] << " " << t[1] << " " << t[2];
  }
  const auto hull = tr.hull_edges();
  for (auto [a, b] : hull)
    for (std::size_t d = 0; d < p.size(); ++d) ASSERT_NE(orient(p[a], p[b], p[d]), NEGATIVE) << "outside the hull";
  // Tiling: every face turns counter-clockwise, so the faces cover the sphere (or the hull) a
  // constant number of times; count it at random points of T².
  const auto q = random_sides(samples, 0.5, p.size() + 17);
  for (const Point& s : q) {
    bool on_boundary = false, outside = false;
    for (auto [a, b] : hull) outside = outside || orient(p[a], p[b], s) != POSITIVE;
    int count = 0;
    for (const Tri& t : tr.finite_triangles()) {
      if (flat(p[t[0]], p[t[1]], p[t[2]])) continue;
      const Sign o0 = orient(p[t[1]], p[t[2]], s), o1 = orient(p[t[2]], p[t[0]], s), o2 = orient(p[t[0]], p[t[1]], s);
      if (o0 < 0 || o1 < 0 || o2 < 0) continue;
      if (o0 == 0 || o1 == 0 || o2 == 0) on_boundary = true;
      ++count;
    }
    if (on_boundary) continue;
    if (any_flat)  // the flat faces (lunes) cover the rest
      EXPECT_LE(count, 1) << "a point covered twice: " << to_string(s);
    else
      EXPECT_EQ(count, !hull.empty() && outside ? 0 : 1) << "point " << to_string(s);
  }
}

inline void expect_brute_force(const std::vector<Point>& pts) {
  const Triangulation tr = delaunay(pts);
  expect_t2_delaunay(tr);
  EXPECT_EQ(proper_faces(tr), brute_force(pts));
}

}  // namespace t2::testing
