// Exercise 09c (the end of the hull) against the library. Its rules (insert.hpp), run by the
// reference solution point by point, give the faces of the library's Algorithm 9
// (t2::triangulate_t2 in input order) whatever the last point is: inside, outside with the hull
// surviving, destroying it, the antipode of a hull vertex (two lunes), or Undefined. And the
// grader refuses a submission that calls one of the library names its manifest forbids.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <fstream>
#include <random>
#include <set>
#include <vector>

#include "../exercises/harness/grader_testing.hpp"
#include "solution/insert.cpp"  // the reference solution of exercises/09c-end-of-hull
#include "t2/kernel/error.hpp"
#include "t2/triangulation/triangulate_t2.hpp"
#include "t2/triangulation/triangulation.hpp"

namespace {

using t2::Point;
using Tri = std::array<long, 3>;
constexpr long I = ex09c::kInfinite;

Tri rotated(Tri t) {
  std::rotate(t.begin(), std::min_element(t.begin(), t.end()), t.end());
  return t;
}

// The triangulation of P[0..n) by the exercise's rules (the first three points not collinear).
std::vector<long> grow(const std::vector<Point>& P, long n) {
  std::vector<long> T = t2::orient(P[0], P[1], P[2]) > 0 ? std::vector<long>{0, 1, 2, 1, 0, I, 2, 1, I, 0, 2, I}
                                                         : std::vector<long>{0, 2, 1, 2, 0, I, 1, 2, I, 0, 1, I};
  for (long q = 3; q < n; ++q) T = ex09c::insert(P, T, q);
  return T;
}

// Inserts the last point of P into the triangulation of the others by the rules and by
// t2::triangulate_t2 in input order; expects the same finite faces and the same hull edges, or
// Undefined from both. Returns 1 when the hull was destroyed, 2 for two lunes, -1 for
// Undefined, 0 otherwise.
int expect_same(const std::vector<Point>& P, const std::string& what) {
  const long q = long(P.size()) - 1;
  const std::vector<long> T = grow(P, q);
  std::vector<long> mine;
  try {
    mine = ex09c::insert(P, T, q);
  } catch (const t2::Undefined&) {
    EXPECT_THROW(t2::triangulate_t2(P, t2::InsertionOrder::input), t2::Undefined) << what;
    return -1;
  }
  const t2::TriangulationT2 lib = t2::triangulate_t2(P, t2::InsertionOrder::input);
  std::set<Tri> faces, hull, lib_faces, lib_hull;
  for (std::size_t k = 0; k < mine.size(); k += 3) {
    const Tri t = rotated({mine[k], mine[k + 1], mine[k + 2]});
    if (t[0] == I) hull.insert({t[2], t[1], 0});  // (v∞, b, a): the hull edge a -> b
    else faces.insert(t);
  }
  for (const auto& t : lib.tr.finite_triangles()) lib_faces.insert(rotated({long(t[0]), long(t[1]), long(t[2])}));
  for (const auto& [a, b] : lib.tr.hull_edges()) lib_hull.insert({long(a), long(b), 0});
  EXPECT_EQ(faces, lib_faces) << what;
  EXPECT_EQ(hull, lib_hull) << what;
  const auto k = ex09c::kinds(P, mine);
  return hull.empty() ? 1 + (std::count(k.begin(), k.end(), ex09c::Kind::lune) == 2) : 0;
}

TEST(Exercise09c, TheRulesAreAlgorithm9) {
  std::mt19937_64 g(2809);
  int destroyed = 0, lunes = 0, undefined = 0;
  auto coordinate = [&](int m) { return double(long(g() % (2 * m + 1)) - m); };
  for (int round = 0; round < 40; ++round) {
    // 14 points of the hemisphere x > 0 (front only in even rounds), a first triangle that is one.
    std::vector<Point> P = {Point(1, 1, 0), Point(1, 4, 0), Point(1, 1, 4)};
    while (P.size() < 14) {
      const double w = round % 2 ? coordinate(3) : double(1 + g() % 3), x = double(1 + g() % 8);
      P.push_back(Point(w, x, coordinate(8)));
    }
    const std::vector<long> T = grow(P, long(P.size()));
    std::vector<long> hull_vertices;
    for (std::size_t k = 0; k < T.size(); k += 3)
      for (int i = 0; i < 3; ++i)
        if (T[k + i] == I) hull_vertices.push_back(T[k + (i + 2) % 3]);
    for (long z : hull_vertices) {  // the antipode of every hull vertex
      std::vector<Point> Q = P;
      Q.push_back(t2::antipode(P[z]));
      const int r = expect_same(Q, "round " + std::to_string(round) + ", ¬ of hull vertex " + std::to_string(z));
      destroyed += r > 0, lunes += r == 2;
    }
    for (int k = 0; k < 20; ++k) {  // anywhere: in the hull, outside it, ¬ inside it, on Ω
      const double w = coordinate(3), x = coordinate(8), y = coordinate(8);
      if (w == 0 && x == 0 && y == 0) continue;
      std::vector<Point> Q = P;
      Q.push_back(Point(w, x, y));
      destroyed += expect_same(Q, "round " + std::to_string(round) + ", point " + std::to_string(k)) > 0;
    }
    for (long z = 0; z < 14; ++z) {  // ¬ of a point halfway between two of P: sometimes inside a hull edge
      const Point& a = P[z];
      const Point& b = P[(z + 1) % 14];
      if (a.w() * b.w() <= 0) continue;
      std::vector<Point> Q = P;
      Q.push_back(t2::antipode(Point(2 * a.w() * b.w(), a.x() * b.w() + b.x() * a.w(), a.y() * b.w() + b.y() * a.w())));
      undefined += expect_same(Q, "round " + std::to_string(round) + ", ¬ of a midpoint " + std::to_string(z)) < 0;
    }
  }
  EXPECT_GT(destroyed, 100);
  EXPECT_GT(lunes, 50);
  EXPECT_GT(undefined, 10);
}

// The grader reads the compiled object's symbols: a solution of 09c that calls the library's
// t2::face_kind (declared by hand, since no allowed header declares it) scores 0, named.
TEST(Exercise09c, TheGraderRefusesTheLibrarysFaceKinds) {
  if (std::getenv("T2_SANITIZED")) GTEST_SKIP() << "grading compiles and runs programs: skipped under sanitizers";
  t2::grader_testing::TempDir t;
  std::ofstream(t.path / "insert.cpp") << R"(#include "insert.hpp"
#include <stdexcept>
namespace t2 {
enum class FaceKind : int;
FaceKind face_kind(const Point& a, const Point& b, const Point& c);
}  // namespace t2
namespace ex09c {
std::vector<Kind> kinds(const std::vector<t2::Point>& P, const std::vector<long>& T) {
  std::vector<Kind> r;
  for (std::size_t k = 0; k + 2 < T.size(); k += 3)
    r.push_back(T[k] < 0 || T[k + 1] < 0 || T[k + 2] < 0 ? Kind::infinite
                : static_cast<Kind>(static_cast<int>(t2::face_kind(P[T[k]], P[T[k + 1]], P[T[k + 2]]))));
  return r;
}
std::vector<long> insert(const std::vector<t2::Point>&, const std::vector<long>&, long) {
  throw std::logic_error("insert() is not implemented yet");
}
}  // namespace ex09c
)";
  const auto r = t2::grader_testing::grade(T2_TOOL, "09c", t.path);
  EXPECT_EQ(r.score, 0);
  EXPECT_NE(r.output.find("your code calls t2::face_kind"), std::string::npos) << r.output;
}

}  // namespace
