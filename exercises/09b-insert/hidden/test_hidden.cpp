// Exercise 09b, hidden tests. Oracle: certificate.hpp (an exact certificate of a triangulated
// sphere with v∞ covering the hull, areas in rationals) and the answer of insert.hpp's rules,
// computed here by brute force. Each test grows a triangulation point by point with those rules
// and asks for every insertion: random points in random order (outside the hull, often), a
// shuffled integer grid with copies (points on edges, on hull edges, on the lines of hull
// edges, equal points), random weights w, points rounded onto edges, and points of an open
// hemisphere that is not the front (back points and points of Ω).
#include <gtest/gtest.h>

#include <algorithm>
#include <random>

#include "certificate.hpp"
#include "insert.hpp"

namespace {

using t2::Point;
constexpr long I = ex09b::kInfinite;

// The rules of insert.hpp, by brute force.
std::vector<long> rule(const std::vector<Point>& P, const std::vector<long>& T, long q) {
  for (long v : T)
    if (v != I && P[v] == P[q]) return T;
  std::vector<ex09btest::Tri> tri;
  for (std::size_t k = 0; k < T.size(); k += 3) tri.push_back({T[k], T[k + 1], T[k + 2]});
  auto flat = [](const std::vector<ex09btest::Tri>& U) {
    std::vector<long> r;
    for (const auto& t : U) r.insert(r.end(), t.begin(), t.end());
    return r;
  };
  for (std::size_t t = 0; t < tri.size(); ++t) {
    const auto [a, b, c] = tri[t];
    if (a == I || b == I || c == I) continue;
    int zero = -1, neg = 0;
    for (int i = 0; i < 3; ++i) {
      const t2::Sign o = t2::orient(P[tri[t][i]], P[tri[t][(i + 1) % 3]], P[q]);
      neg += o < 0;
      if (o == 0) zero = i;
    }
    if (neg) continue;
    if (zero < 0) {
      tri.erase(tri.begin() + long(t));
      tri.insert(tri.end(), {{a, b, q}, {b, c, q}, {c, a, q}});
      return flat(tri);
    }
    const long u = tri[t][zero], v = tri[t][(zero + 1) % 3], w = tri[t][(zero + 2) % 3];
    for (std::size_t s = 0; s < tri.size(); ++s)
      for (int i = 0; i < 3; ++i)
        if (tri[s][i] == v && tri[s][(i + 1) % 3] == u) {
          const long d = tri[s][(i + 2) % 3];
          tri.erase(tri.begin() + long(std::max(s, t)));
          tri.erase(tri.begin() + long(std::min(s, t)));
          tri.insert(tri.end(), {{u, q, w}, {q, v, w}, {v, q, d}, {q, u, d}});
          return flat(tri);
        }
  }
  // Outside: the seen infinite triangles, a chain along the hull from `first` to `last`.
  long first = I, last = I;
  std::vector<ex09btest::Tri> out;
  std::vector<std::pair<long, long>> seen;
  for (auto t : tri) {
    std::rotate(t.begin(), std::find(t.begin(), t.end(), I), t.end());  // (inf, a, b): edge a -> b
    if (t[0] == I && t2::orient(P[t[1]], P[t[2]], P[q]) > 0) {
      out.push_back({t[1], t[2], q});
      seen.push_back({t[1], t[2]});
    } else {
      out.push_back(t);
    }
  }
  for (const auto& [a, b] : seen) {
    if (std::none_of(seen.begin(), seen.end(), [&](const auto& e) { return e.second == a; })) first = a;
    if (std::none_of(seen.begin(), seen.end(), [&](const auto& e) { return e.first == b; })) last = b;
  }
  out.insert(out.end(), {{first, q, I}, {q, last, I}});
  return flat(out);
}

// Grows a triangulation of P in the order given (the first three not collinear), checking
// the answer of every insertion; `pole` holds P in its open hemisphere (certificate.hpp).
void grow(const std::vector<Point>& P, const Point& pole = Point(1, 0, 0)) {
  std::size_t k = 2;
  while (t2::orient(P[0], P[1], P[k]) == t2::ZERO) ++k;
  std::vector<long> T = t2::orient(P[0], P[1], P[k]) > 0
                            ? std::vector<long>{0, 1, long(k), 1, 0, I, long(k), 1, I, 0, long(k), I}
                            : std::vector<long>{0, long(k), 1, long(k), 0, I, 1, long(k), I, 0, 1, I};
  for (long q = 2; q < long(P.size()); ++q) {
    if (q == long(k)) continue;
    const std::vector<long> want = rule(P, T, q);
    EXPECT_EQ(ex09btest::check(P, T, q, ex09b::insert(P, T, q), want, pole), "") << "inserting point " << q;
    T = want;
  }
}

double unit(std::mt19937_64& g) { return double(g() >> 11) * 0x1p-53; }

TEST(Hidden, RandomInsertions) {
  std::mt19937_64 g(9);
  for (int round = 0; round < 3; ++round) {
    std::vector<Point> P;
    for (int k = 0; k < 40; ++k) P.push_back(Point::cartesian(unit(g), unit(g)));
    grow(P);
  }
}

TEST(Hidden, GridWithDuplicates) {
  std::vector<Point> P;
  for (int k = 0; k < 25; ++k) P.push_back(Point::cartesian(k % 5, k / 5));
  for (int k = 0; k < 25; k += 6) P.push_back(Point(3, 3.0 * (k % 5), 3.0 * (k / 5)));  // equal in T²
  std::shuffle(P.begin() + 3, P.end(), std::mt19937_64(95));
  P.insert(P.begin(), {Point::cartesian(0, 0), Point::cartesian(1, 0), Point::cartesian(2, 0)});
  grow(P);
}

TEST(Hidden, Homogeneous) {
  std::mt19937_64 g(99);
  const double w[] = {0.5, 2, 3, 7, 1e-3, 1e3};
  std::vector<Point> P;
  for (int k = 0; k < 40; ++k) {
    const double s = w[g() % 6];
    P.push_back(Point(s, s * std::floor(16 * unit(g)), s * std::floor(16 * unit(g))));
  }
  grow(P);
}

// Points of T² in the open hemisphere x > 0 (pole [0, 1, 0]): front, back (w < 0) and on Ω
// (w = 0), some with a copy scaled by 3 (equal in T²). A back point [w, x, y] is drawn at
// (x/w, y/w), where its antipode is: a solution that orients drawn positions gets every
// triangle with an odd number of back vertices backwards.
TEST(Hidden, Hemisphere) {
  std::mt19937_64 g(909);
  std::vector<Point> P;
  for (int k = 0; k < 40; ++k) {
    const double w = double(long(g() % 13) - 6), x = double(1 + g() % 16), y = double(long(g() % 33) - 16);
    P.push_back(Point(w, x, y));
    if (k % 8 == 7) P.push_back(Point(3 * w, 3 * x, 3 * y));
  }
  long back = 0, omega = 0;
  for (const Point& p : P) back += p.w() < 0, omega += p.w() == 0;
  ASSERT_GE(back, 10);
  ASSERT_GE(omega, 2);
  grow(P, Point(0, 1, 0));
}

// Points a + t(b − a), rounded to doubles, on the edges of a triangulation of random points:
// off the line by the rounding, by less than a determinant evaluated in doubles can tell.
TEST(Hidden, NearlyOnEdges) {
  std::mt19937_64 g(999);
  std::vector<Point> P;
  for (int k = 0; k < 25; ++k) P.push_back(Point::cartesian(unit(g), unit(g)));
  std::vector<long> T = {0, 1, 2};
  if (t2::orient(P[0], P[1], P[2]) < 0) std::swap(T[1], T[2]);
  T.insert(T.end(), {T[1], T[0], I, T[2], T[1], I, T[0], T[2], I});
  for (long q = 3; q < 25; ++q) T = rule(P, T, q);
  for (int k = 0; k < 120; ++k) {
    std::size_t t = 3 * (g() % (T.size() / 3));
    while (T[t] == I || T[t + 1] == I || T[t + 2] == I) t = 3 * (g() % (T.size() / 3));
    const Point &a = P[T[t]], &b = P[T[t + 1]];
    const double s = unit(g);
    std::vector<Point> Q = P;
    Q.push_back(Point::cartesian(a.x() + s * (b.x() - a.x()), a.y() + s * (b.y() - a.y())));
    EXPECT_EQ(ex09btest::check(Q, T, 25, ex09b::insert(Q, T, 25), rule(Q, T, 25)), "") << k;
  }
}

}  // namespace
