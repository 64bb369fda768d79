// The structural operations of t2::Triangulation, one at a time: the first triangle with its
// three infinite triangles, insertion in a face, on an inner and a hull edge, outside the hull,
// flips, the walk, renaming a vertex. After each operation the invariants hold (validate) and the
// triangles are the expected ones.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <string>

#include "t2/kernel/orient.hpp"
#include "t2/triangulation/triangulate_t2.hpp"
#include "t2/triangulation/triangulation.hpp"
#include "testing.hpp"

namespace t2 {
namespace {

using Index = Triangulation::Index;
using Tri = std::array<Index, 3>;
constexpr Index inf = Triangulation::infinite;

std::vector<Tri> sorted(std::vector<Tri> t) {
  std::sort(t.begin(), t.end());
  return t;
}

/// All triangles, infinite ones included, each rotated so that its smallest index comes first
/// (v∞ is the largest index).
std::vector<Tri> all_triangles(const Triangulation& tr) {
  std::vector<Tri> out;
  for (Index t = 0; t < tr.size(); ++t) {
    Tri r = {tr.vertex(t, 0), tr.vertex(t, 1), tr.vertex(t, 2)};
    std::rotate(r.begin(), std::min_element(r.begin(), r.end()), r.end());
    out.push_back(r);
  }
  return sorted(out);
}

auto orient_fn = [](const Point& p, const Point& q, const Point& r) { return orient(p, q, r); };

// 0 (0,0), 1 (4,0), 2 (0,4), 3 (1,1) inside, 4 (2,0) on the hull edge 0–1, 5 (2,2) on the edge 1–2,
// 6 (4,4) outside, 7 (1,1) again, 8 (1,2) on the segment 4–2.
std::vector<Point> sample() {
  return {Point::cartesian(0, 0), Point::cartesian(4, 0), Point::cartesian(0, 4), Point::cartesian(1, 1),
          Point::cartesian(2, 0), Point::cartesian(2, 2), Point::cartesian(4, 4), Point::cartesian(1, 1), Point::cartesian(1, 2)};
}

TEST(Triangulation, FirstTriangle) {
  Triangulation tr(sample());
  tr.make_triangle(0, 1, 2);
  EXPECT_EQ(tr.validate(), "");
  EXPECT_EQ(tr.size(), 4u);
  EXPECT_EQ(all_triangles(tr), sorted({{0, 1, 2}, {0, 2, inf}, {0, inf, 1}, {1, inf, 2}}));
  EXPECT_EQ(tr.hull_edges(), (std::vector<std::pair<Index, Index>>{{0, 1}, {1, 2}, {2, 0}}));
}

TEST(Triangulation, ClockwiseFirstTriangleIsInvalid) {
  Triangulation tr(sample());
  tr.make_triangle(0, 2, 1);
  EXPECT_NE(tr.validate(), "");
}

TEST(Triangulation, InsertInFaceAndLocate) {
  Triangulation tr(sample());
  tr.make_triangle(0, 1, 2);
  std::uint32_t rng = 1;
  for (Index start = 0; start < 4; ++start) {
    const auto loc = tr.locate(tr.point(3), start, orient_fn, rng);
    EXPECT_EQ(loc.kind, Triangulation::Location::face);
    EXPECT_EQ(loc.t, 0u);
  }
  tr.insert_in_face(0, 3);
  EXPECT_EQ(tr.validate(), "");
  EXPECT_EQ(tr.finite_triangles().size(), 3u);
  for (Index t = 0; t < tr.size(); ++t) EXPECT_EQ(tr.vertex(t, 0) == 3, t == 0 || t >= 4);
  // The duplicate of 3 is found on the vertex, from every start.
  for (Index start = 0; start < tr.size(); ++start) {
    const auto loc = tr.locate(tr.point(7), start, orient_fn, rng);
    ASSERT_EQ(loc.kind, Triangulation::Location::vertex);
    EXPECT_EQ(tr.vertex(loc.t, loc.i), 3u);
  }
}

TEST(Triangulation, InsertOnHullEdgeAndInnerEdge) {
  Triangulation tr(sample());
  tr.make_triangle(0, 1, 2);
  std::uint32_t rng = 7;
  auto loc = tr.locate(tr.point(4), 0, orient_fn, rng);
  ASSERT_EQ(loc.kind, Triangulation::Location::edge);
  tr.insert_on_edge(loc.t, loc.i, 4);
  EXPECT_EQ(tr.validate(), "");
  EXPECT_EQ(sorted(tr.finite_triangles()), sorted({{0, 4, 2}, {1, 2, 4}}));
  EXPECT_EQ(tr.hull_edges(), (std::vector<std::pair<Index, Index>>{{0, 4}, {1, 2}, {2, 0}, {4, 1}}));
  loc = tr.locate(tr.point(5), 3, orient_fn, rng);  // (2,2) is on the hull edge 1–2
  ASSERT_EQ(loc.kind, Triangulation::Location::edge);
  tr.insert_on_edge(loc.t, loc.i, 5);
  loc = tr.locate(tr.point(8), 0, orient_fn, rng);  // (1,2) is on the inner edge 4–2
  ASSERT_EQ(loc.kind, Triangulation::Location::edge);
  tr.insert_on_edge(loc.t, loc.i, 8);
  EXPECT_EQ(tr.validate(), "");
  EXPECT_EQ(sorted(tr.finite_triangles()), sorted({{0, 4, 8}, {0, 8, 2}, {4, 5, 8}, {2, 8, 5}, {1, 5, 4}}));
}

TEST(Triangulation, InsertOutsideHullThenFlip) {
  Triangulation tr(sample());
  tr.make_triangle(0, 1, 2);
  std::uint32_t rng = 3;
  const auto loc = tr.locate(tr.point(6), 0, orient_fn, rng);  // (4,4) sees only the edge 1–2
  ASSERT_EQ(loc.kind, Triangulation::Location::face);
  ASSERT_TRUE(tr.is_infinite(loc.t));
  tr.insert_in_face(loc.t, 6);
  EXPECT_EQ(tr.validate(), "");
  EXPECT_EQ(sorted(tr.finite_triangles()), sorted({{0, 1, 2}, {1, 6, 2}}));
  // Flip the diagonal 1–2 of the quadrilateral 0, 1, 6, 2 and back.
  const Index t = loc.t;  // (6, 1, 2) after the insertion: 6 is vertex 0
  ASSERT_EQ(tr.vertex(t, 0), 6u);
  ASSERT_FALSE(tr.is_infinite(t));
  const Index u = tr.neighbor(t, 0);
  tr.flip(t, 0);
  EXPECT_EQ(tr.validate(), "");
  EXPECT_EQ(sorted(tr.finite_triangles()), sorted({{0, 1, 6}, {0, 6, 2}}));
  EXPECT_EQ(tr.vertex(t, 0), 6u);
  EXPECT_EQ(tr.vertex(u, 0), 6u);
  tr.flip(t, 1);  // the edge 0–6 is opposite vertex 2, slot 1 of t = (6, 2, 0)
  EXPECT_EQ(tr.validate(), "");
  EXPECT_EQ(sorted(tr.finite_triangles()), sorted({{0, 1, 2}, {1, 6, 2}}));
}

TEST(Triangulation, RenameVertex) {
  Triangulation tr(sample());
  tr.make_triangle(0, 1, 2);
  tr.insert_in_face(0, 7);
  tr.rename_vertex(0, 7, 3);
  EXPECT_EQ(tr.validate(), "");
  EXPECT_EQ(sorted(tr.finite_triangles()), sorted({{0, 1, 3}, {1, 2, 3}, {0, 3, 2}}));
}

// The walk on random triangulations built by insertions in faces only (not Delaunay): it finds
// the triangle that contains each query point, checked by exact orientations.
TEST(Triangulation, WalkFindsContainingTriangle) {
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> u(0.01, 0.99);
  std::vector<Point> pts = {Point::cartesian(0, 0), Point::cartesian(1, 0), Point::cartesian(0, 1)};
  for (int k = 0; k < 200 * testing::scale(); ++k) {
    const double x = u(rng), y = u(rng);
    if (x + y < 0.99) pts.push_back(Point::cartesian(x, y));
  }
  Triangulation tr(pts);
  tr.make_triangle(0, 1, 2, pts.size());
  std::uint32_t state = 9;
  for (Index p = 3; p < pts.size(); ++p) {
    const auto loc = tr.locate(pts[p], 0, orient_fn, state);
    ASSERT_EQ(loc.kind, Triangulation::Location::face);
    for (int i = 0; i < 3; ++i)
      ASSERT_EQ(orient(tr.point(tr.vertex(loc.t, (i + 1) % 3)), tr.point(tr.vertex(loc.t, (i + 2) % 3)), pts[p]),
                POSITIVE);
    tr.insert_in_face(loc.t, p);
  }
  EXPECT_EQ(tr.validate(), "");
  EXPECT_EQ(tr.finite_triangles().size(), 2 * pts.size() - 5);
}

TEST(Triangulation, ValidateFindsBrokenTwins) {
  Triangulation tr(sample());
  tr.make_triangle(0, 1, 2);
  tr.insert_in_face(0, 3);
  Triangulation bad = tr;
  bad.rename_vertex(0, 3, 1);  // vertex 1 twice: pinched star, degenerate triangles
  EXPECT_NE(bad.validate(), "");
}

// The arrays of tr, to be broken and handed to `assign`.
struct Arrays {
  std::vector<Index> v, n;
};
Arrays arrays(const Triangulation& tr) {
  Arrays a;
  for (Index t = 0; t < tr.size(); ++t)
    for (int i = 0; i < 3; ++i) a.v.push_back(tr.vertex(t, i)), a.n.push_back(tr.twin(t, i));
  return a;
}
Triangulation with(const Triangulation& tr, Arrays a) {
  Triangulation out(tr.points());
  out.assign(std::move(a.v), std::move(a.n));
  out.set_antipodal_edges(tr.antipodal_edges());
  return out;
}

bool has(const std::string& s, const std::string& part) { return s.find(part) != std::string::npos; }

// Seed 000's figure 5.19 (Algorithm 9 in input order, triangulate_t2.hpp): a legitimate flat
// face passes; the same arrays with every face turned round, or with two twins exchanged, fail.
// A flat face whose vertices lie in no open half of their great circle fails, and so does a flat
// face in a triangulation with v∞.
TEST(Triangulation, ValidateAcceptsTheFlatFacesOfT2AndNothingBroken) {
  const Point z = Point::cartesian(0, 0), w = Point::cartesian(2, 0), u = Point::cartesian(3, 4);
  const TriangulationT2 r =
      triangulate_t2(std::vector<Point>{z, w, u, antipode(z), Point::cartesian(1, 0)}, InsertionOrder::input);
  const Triangulation& tr = r.tr;
  Index flat = Triangulation::none;
  for (Index t = 0; t < tr.size(); ++t)
    if (face_kind(tr, t) == FaceKind::flat) flat = t;
  ASSERT_NE(flat, Triangulation::none);
  EXPECT_EQ(tr.validate(), "");
  EXPECT_EQ(with(tr, arrays(tr)).validate(), "");
  // invariant 6: the antipodal edge z – ¬z without its record, or with two
  Triangulation bare = with(tr, arrays(tr));
  bare.set_antipodal_edges({});
  EXPECT_TRUE(has(bare.validate(), "has 0 records")) << bare.validate();
  bare.set_antipodal_edges({tr.antipodal_edges()[0], tr.antipodal_edges()[0]});
  EXPECT_TRUE(has(bare.validate(), "has 2 records")) << bare.validate();
  // every face turned round: slots 1 and 2 exchanged, in the vertices and in the twins' slots
  const Arrays a = arrays(tr);
  Arrays mirror = a;
  auto swap12 = [](Index e) { return e % 3 == 0 ? e : e % 3 == 1 ? e + 1 : e - 1; };
  for (Index e = 0; e < a.v.size(); ++e) {
    mirror.v[e] = a.v[swap12(e)];
    mirror.n[e] = swap12(a.n[swap12(e)]);
  }
  const std::string turned = with(tr, mirror).validate();
  EXPECT_TRUE(has(turned, "not counter-clockwise")) << turned;
  Arrays twins = a;  // a bad neighbour: two twins of the flat face exchanged
  std::swap(twins.n[3 * flat], twins.n[3 * flat + 1]);
  EXPECT_TRUE(has(with(tr, twins).validate(), "twin")) << with(tr, twins).validate();
  // A tetrahedron whose face 0 is flat on the circle y = 0 at 45°, 63° and 230°: in no open half.
  Triangulation spread(std::vector<Point>{Point(1, 1, 0), Point(1, 2, 0), Point(-5, -6, 0), Point(1, 0, 1)});
  spread.assemble({{0, 1, 2}, {1, 0, 3}, {2, 1, 3}, {0, 2, 3}});
  EXPECT_TRUE(has(spread.validate(), "no open half")) << spread.validate();
  // a flat face with v∞: a, m, c on a line, and the three infinite faces of its edges
  Triangulation line(std::vector<Point>{Point::cartesian(0, 0), Point::cartesian(1, 0), Point::cartesian(2, 0)});
  line.assemble({{0, 1, 2}, {1, 0, inf}, {2, 1, inf}, {0, 2, inf}});
  EXPECT_TRUE(has(line.validate(), "while v∞ is a vertex")) << line.validate();
}

}  // namespace
}  // namespace t2
