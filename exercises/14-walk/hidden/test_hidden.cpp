// Exercise 14, hidden tests. Oracle: every face in order with the exact point-in-polygon test of
// T² (point_in_polygon.hpp's `locate`, seed 000 Algorithm 2), then point equality for a vertex
// and `on_segment` for an edge: the first face that holds the query is the least. Inputs: the
// octahedron (eight faces covering T², vertices and edges on Ω), grids on the back side drawn
// over grids on the front, grids moved by random projective maps so that faces cross Ω and the
// complement wraps around it, queries on vertices and edges in random order, and two 200 × 200
// grids (160 000 faces) with 100 000 queries in row order, where testing every face is ~10¹⁰
// orientations and a walk a few per query.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <tuple>

#include <t2/kernel/orient.hpp>
#include <t2/kernel/point.hpp>
#include <t2/kernel/point_in_polygon.hpp>
#include <t2/kernel/segment.hpp>

#include "walk.hpp"

namespace {

using ex14::Location;
using ex14::Triangle;
using t2::Point;
using K = Location::Kind;

struct Map {
  std::vector<Point> P;
  std::vector<Triangle> T;
};

Location oracle(const Map& m, const Point& q) {
  for (int f = 0; f < int(m.T.size()); ++f) {
    const t2::Polygon F = {m.P[m.T[f][0]], m.P[m.T[f][1]], m.P[m.T[f][2]]};
    const t2::Sign s = t2::locate(F, q);
    if (s == t2::POSITIVE) return {K::face, f, 0};
    if (s == t2::ZERO) {
      for (int k = 0; k < 3; ++k)
        if (F[k] == q) return {K::vertex, f, k};
      for (int k = 0; k < 3; ++k)
        if (t2::on_segment(F[k], F[(k + 1) % 3], q)) return {K::edge, f, k};
      ADD_FAILURE() << "oracle: on the boundary of face " << f << " but on no vertex or edge";
    }
  }
  return {};
}

std::string show(const Location& l) {
  const char* k[] = {"face", "edge", "vertex", "outside"};
  return std::string(k[int(l.kind) & 3]) + " " + std::to_string(l.face) + " " + std::to_string(l.k);
}

// Runs the student's code on every query and compares with the oracle, query by query.
void check(const Map& m, const std::vector<Point>& Q, const char* what) {
  const auto got = ex14::locate_all(m.P, m.T, Q);
  ASSERT_EQ(got.size(), Q.size()) << what << ": one answer per query";
  int wrong = 0;
  for (std::size_t i = 0; i < Q.size() && wrong < 5; ++i) {
    const Location want = oracle(m, Q[i]);
    if (!(got[i] == want)) {
      ++wrong;
      ADD_FAILURE() << what << ": query " << i << " " << t2::to_string(Q[i]) << ": got " << show(got[i])
                    << ", want " << show(want);
    }
  }
}

// A 3 × 3 integer matrix with positive determinant: a projective map of T² that keeps every
// orientation, so faces stay counter-clockwise, and moves part of a map across Ω.
struct Projective {
  long a[3][3];
  Point operator()(const Point& p) const {
    const double c[3] = {p.w(), p.x(), p.y()};
    double r[3];
    for (int i = 0; i < 3; ++i) r[i] = a[i][0] * c[0] + a[i][1] * c[1] + a[i][2] * c[2];  // small integers: exact
    return Point(r[0], r[1], r[2]);
  }
};
const Projective kIdentity{{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}};

Projective random_map(std::mt19937_64& g) {
  for (;;) {
    Projective M;
    for (auto& row : M.a)
      for (long& v : row) v = long(g() % 5) - 2;
    const long d = M.a[0][0] * (M.a[1][1] * M.a[2][2] - M.a[1][2] * M.a[2][1]) -
                   M.a[0][1] * (M.a[1][0] * M.a[2][2] - M.a[1][2] * M.a[2][0]) +
                   M.a[0][2] * (M.a[1][0] * M.a[2][1] - M.a[1][1] * M.a[2][0]);
    if (d == 0) continue;
    if (d < 0)
      for (long& v : M.a[0]) v = -v;
    return M;
  }
}

// Appends an nx × ny grid of unit cells with corner (x0, y0), on the side of the weight w
// (front w > 0, back w < 0), two faces per cell, moved by M.
void add_grid(Map& m, int nx, int ny, double x0, double y0, double w, const Projective& M) {
  const int base = int(m.P.size());
  for (int j = 0; j <= ny; ++j)
    for (int i = 0; i <= nx; ++i) m.P.push_back(M(Point(w, w * (x0 + i), w * (y0 + j))));
  const auto v = [&](int i, int j) { return base + j * (nx + 1) + i; };
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      const int a = v(i, j), b = v(i + 1, j), c = v(i + 1, j + 1), d = v(i, j + 1);
      if (w > 0) {
        m.T.push_back({a, b, c});
        m.T.push_back({a, c, d});
      } else {  // drawn counter-clockwise is clockwise in T² on the back side
        m.T.push_back({a, c, b});
        m.T.push_back({a, d, c});
      }
    }
}

// Faces in random order, each starting at a random vertex: the least face is anywhere.
void shuffle(Map& m, std::mt19937_64& g) {
  std::shuffle(m.T.begin(), m.T.end(), g);
  for (auto& t : m.T) std::rotate(t.begin(), t.begin() + g() % 3, t.end());
}

// Queries around the pre-image of a grid map: random proper points with denominators 2-5 on
// both sides (many on edges and vertices), points of Ω, vertices, midpoints of edges, antipodes.
std::vector<Point> queries(const Map& m, std::mt19937_64& g, const Projective& M, int n) {
  std::vector<Point> Q;
  while (int(Q.size()) < n) {
    const double d = double(g() % 4 + 2), x = double(g() % 41) - 20, y = double(g() % 41) - 20;
    const auto& t = m.T[g() % m.T.size()];
    switch (g() % 6) {
      case 0: Q.push_back(M(Point(d, x, y))); break;
      case 1: Q.push_back(M(Point(-d, -x, -y))); break;
      case 2: if (x != 0 || y != 0) Q.push_back(M(Point(0, x, y))); break;
      case 3: Q.push_back(m.P[t[g() % 3]]); break;
      case 4: {
        const Point &a = m.P[t[0]], &b = m.P[t[1]];
        Q.push_back(Point(a.w() + b.w(), a.x() + b.x(), a.y() + b.y()));  // small integers: exact
        break;
      }
      default: Q.push_back(t2::antipode(m.P[t[g() % 3]]));
    }
  }
  return Q;
}

Map octahedron() {
  Map m;
  m.P = {Point(1, 0, 0), Point(-1, 0, 0), Point(0, 1, 0), Point(0, -1, 0), Point(0, 0, 1), Point(0, 0, -1)};
  for (int s = 0; s < 8; ++s) {
    const int a = s & 4 ? 1 : 0, b = s & 2 ? 3 : 2, c = s & 1 ? 5 : 4;
    if (__builtin_popcount(s) % 2 == 0)
      m.T.push_back({a, b, c});
    else
      m.T.push_back({a, c, b});
  }
  return m;
}

TEST(Hidden, Octahedron) {
  std::mt19937_64 g(1401);
  Map m = octahedron();
  std::vector<Point> Q;
  for (int k = 0; k < 400; ++k) {
    const double w = double(int(g() % 5) - 2), x = double(int(g() % 5) - 2), y = double(int(g() % 5) - 2);
    if (w != 0 || x != 0 || y != 0) Q.push_back(Point(w, x, y));
  }
  check(m, Q, "octahedron");
  shuffle(m, g);
  check(m, Q, "octahedron, faces shuffled");
}

TEST(Hidden, BackSide) {
  // A front grid and a back grid drawn over it, shifted by half a cell: every drawn spot is in
  // a face of each side; a drawn view that ignores the side answers the wrong one.
  std::mt19937_64 g(1402);
  Map m;
  add_grid(m, 6, 5, -3, -3, 1, kIdentity);
  add_grid(m, 5, 6, -2, -2, -2, kIdentity);
  check(m, queries(m, g, kIdentity, 600), "front and back grids");
  shuffle(m, g);
  check(m, queries(m, g, kIdentity, 600), "front and back grids, faces shuffled");
}

TEST(Hidden, AcrossOmega) {
  std::mt19937_64 g(1403);
  for (int r = 0; r < 8; ++r) {
    const Projective M = random_map(g);
    Map m;
    add_grid(m, 5, 4, -2, -2, 1, M);
    add_grid(m, 3, 3, 4, 4, -1, M);
    if (r % 2) shuffle(m, g);
    check(m, queries(m, g, M, 300), "grids across Ω");
  }
}

TEST(Hidden, VerticesAndEdges) {
  // Only vertices and points inside edges, in random order: the walk reaches them from any
  // face around, and the answer must still name the least face.
  std::mt19937_64 g(1404);
  for (int r = 0; r < 4; ++r) {
    const Projective M = r == 0 ? kIdentity : random_map(g);
    Map m;
    add_grid(m, 6, 6, -3, -3, r % 2 ? -1 : 1, M);
    shuffle(m, g);
    std::vector<Point> Q;
    for (int k = 0; k < 300; ++k) {
      const auto& t = m.T[g() % m.T.size()];
      const int i = int(g() % 3);
      const Point &a = m.P[t[i]], &b = m.P[t[(i + 1) % 3]];
      Q.push_back(k % 2 ? a : Point(a.w() + b.w(), a.x() + b.x(), a.y() + b.y()));
    }
    check(m, Q, "vertices and edges");
  }
}

TEST(Hidden, LargeGrids) {
  // 200 × 200 cells on the front and the same drawn on the back: 160 000 faces. 50 000 queries
  // per side strictly inside cells, off the diagonals, in row order, then a few on vertices, on
  // edges and outside. The face of a cell query is known by construction; a sample of them and
  // every special query are checked with the oracle.
  const int n = 200;
  std::mt19937_64 g(1405);
  Map m;
  add_grid(m, n, n, 0, 0, 1, kIdentity);
  add_grid(m, n, n, 0, 0, -1, kIdentity);
  std::vector<Point> Q;
  std::vector<Location> want;
  for (const double s : {1.0, -1.0}) {
    struct Cell {
      int i, j, u, v;
    };
    std::vector<Cell> C;
    for (int k = 0; k < 50000; ++k) {
      Cell c{int(g() % n), int(g() % n), int(g() % 7) + 1, int(g() % 7) + 1};
      if (c.u == c.v) c.v = c.u % 7 + 1;
      C.push_back(c);
    }
    std::sort(C.begin(), C.end(), [](const Cell& a, const Cell& b) {
      return std::tie(a.j, a.i, a.u, a.v) < std::tie(b.j, b.i, b.u, b.v);
    });
    const int base = s > 0 ? 0 : 2 * n * n;
    for (const Cell& c : C) {
      Q.push_back(Point(8 * s, s * (8 * c.i + c.u), s * (8 * c.j + c.v)));  // (i + u/8, j + v/8)
      want.push_back({K::face, base + 2 * (c.j * n + c.i) + (c.v < c.u ? 0 : 1), 0});
    }
  }
  const std::size_t cells = Q.size();
  for (int k = 0; k < 20; ++k) {
    const Triangle& t = m.T[g() % m.T.size()];
    const Point &a = m.P[t[0]], &b = m.P[t[1]];
    Q.push_back(a);
    Q.push_back(Point(a.w() + b.w(), a.x() + b.x(), a.y() + b.y()));
    Q.push_back(Point(k % 2 ? 1 : -1, double(k % 2 ? 1 : -1) * (n + 1 + k), 3));  // right of a grid
  }
  const auto got = ex14::locate_all(m.P, m.T, Q);
  ASSERT_EQ(got.size(), Q.size());
  int wrong = 0;
  for (std::size_t i = 0; i < cells && wrong < 5; ++i)
    if (!(got[i] == want[i])) {
      ++wrong;
      ADD_FAILURE() << "query " << i << " " << t2::to_string(Q[i]) << ": got " << show(got[i]) << ", want "
                    << show(want[i]);
    }
  for (std::size_t i = 0; i < cells; i += 2500) ASSERT_TRUE(oracle(m, Q[i]) == want[i]) << "the test's construction";
  for (std::size_t i = cells; i < Q.size() && wrong < 5; ++i)
    if (const Location w = oracle(m, Q[i]); !(got[i] == w)) {
      ++wrong;
      ADD_FAILURE() << "query " << i << " " << t2::to_string(Q[i]) << ": got " << show(got[i]) << ", want "
                    << show(w);
    }
}

}  // namespace
