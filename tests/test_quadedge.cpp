// The quad-edge of t2/triangulation/quadedge.hpp: the edge algebra's identities (Guibas and
// Stolfi 1985, §2.4) on every quarter-edge of built subdivisions, make_edge's rings, splice as
// its own inverse, and a triangle built by connect and taken apart by delete_edge, its rings
// and faces counted by walking them.
#include <gtest/gtest.h>

#include <set>
#include <vector>

#include "t2/triangulation/quadedge.hpp"

namespace t2 {
namespace {

using Edge = QuadEdge::Edge;

// The identities every quarter-edge of every subdivision satisfies; `with_origins`: also that
// the stored origins agree with the rings (splice changes rings, not origins: a splice that
// joins two vertices leaves that to its caller).
void expect_algebra(const QuadEdge& q, bool with_origins = true) {
  for (Edge e = 0; e < 4 * q.quads(); ++e) {
    if (q.is_deleted(e)) continue;
    EXPECT_EQ(QuadEdge::rot(QuadEdge::rot(QuadEdge::rot(QuadEdge::rot(e)))), e);
    EXPECT_NE(QuadEdge::rot(QuadEdge::rot(e)), e);
    EXPECT_EQ(QuadEdge::rot(QuadEdge::rot(e)), QuadEdge::sym(e));
    EXPECT_EQ(QuadEdge::rot_inv(QuadEdge::rot(e)), e);
    EXPECT_EQ(q.onext(q.oprev(e)), e);                                  // Onext⁻¹ = Oprev
    EXPECT_EQ(q.lprev(q.lnext(e)), e);
    EXPECT_EQ(q.rprev(q.rnext(e)), e);
    EXPECT_EQ(QuadEdge::rot(q.onext(QuadEdge::rot(q.onext(e)))), e);   // e Onext Rot Onext Rot = e
    EXPECT_EQ(q.onext(QuadEdge::sym(e)), q.rprev(e));
    EXPECT_EQ(q.dnext(e), QuadEdge::sym(q.onext(QuadEdge::sym(e))));
    if (with_origins && (e & 1u) == 0) {  // primal: the left face's edges share their endpoints head to tail
      EXPECT_EQ(q.org(q.lnext(e)), q.dest(e));
      EXPECT_EQ(q.org(q.onext(e)), q.org(e));
    }
  }
}

// The length of the orbit of e under f.
template <class F>
int orbit(Edge e, F f) {
  int k = 0;
  Edge x = e;
  do {
    x = f(x);
    ++k;
  } while (x != e && k < 100);
  return k;
}

TEST(QuadEdge, MakeEdgeIsAlone) {
  QuadEdge q;
  const Edge e = q.make_edge(7, 9);
  EXPECT_EQ(q.org(e), 7u);
  EXPECT_EQ(q.dest(e), 9u);
  EXPECT_EQ(q.onext(e), e);                          // its own ring at each end
  EXPECT_EQ(q.onext(QuadEdge::sym(e)), QuadEdge::sym(e));
  EXPECT_EQ(q.lnext(e), QuadEdge::sym(e));           // one face, on both sides
  EXPECT_EQ(orbit(QuadEdge::rot(e), [&](Edge x) { return q.onext(x); }), 2);
  expect_algebra(q);
}

TEST(QuadEdge, SpliceIsItsOwnInverse) {
  QuadEdge q;
  const Edge a = q.make_edge(0, 1), b = q.make_edge(1, 2), c = q.make_edge(1, 3);
  q.splice(QuadEdge::sym(a), b);
  q.splice(b, c);
  std::vector<Edge> before;
  for (Edge e = 0; e < 4 * q.quads(); ++e) before.push_back(q.onext(e));
  for (Edge x : {a, QuadEdge::sym(a), b, c})
    for (Edge y : {b, QuadEdge::sym(b), c, QuadEdge::sym(c)}) {
      q.splice(x, y);
      expect_algebra(q, false);
      q.splice(x, y);
      expect_algebra(q);
      for (Edge e = 0; e < 4 * q.quads(); ++e) ASSERT_EQ(q.onext(e), before[e]);
    }
  // Vertex 1 has a ring of three edges: sym(a), b, c.
  EXPECT_EQ(orbit(b, [&](Edge x) { return q.onext(x); }), 3);
}

// A triangle by two edges and connect; its inner face and outer face have three edges each;
// every vertex two. delete_edge takes it back to a path, and the freed quad is reused.
TEST(QuadEdge, ConnectAndDelete) {
  QuadEdge q;
  const Edge a = q.make_edge(0, 1), b = q.make_edge(1, 2);
  q.splice(QuadEdge::sym(a), b);
  const Edge c = q.connect(b, a);  // from 2 to 0, closing the left face of a and b
  EXPECT_EQ(q.org(c), 2u);
  EXPECT_EQ(q.dest(c), 0u);
  EXPECT_EQ(q.lnext(a), b);
  EXPECT_EQ(q.lnext(b), c);
  EXPECT_EQ(q.lnext(c), a);
  EXPECT_EQ(orbit(QuadEdge::sym(a), [&](Edge x) { return q.lnext(x); }), 3);  // the outer face
  for (Edge e : {a, b, c}) EXPECT_EQ(orbit(e, [&](Edge x) { return q.onext(x); }), 2);
  // The dual: two faces, each a vertex of the dual with a ring of three dual edges.
  EXPECT_EQ(orbit(QuadEdge::rot(a), [&](Edge x) { return q.onext(x); }), 3);
  expect_algebra(q);
  q.delete_edge(c);
  EXPECT_TRUE(q.is_deleted(c));
  EXPECT_EQ(q.lnext(a), b);
  EXPECT_EQ(q.lnext(b), QuadEdge::sym(b));  // a path again: one face
  EXPECT_EQ(orbit(a, [&](Edge x) { return q.lnext(x); }), 4);
  expect_algebra(q);
  const Edge d = q.make_edge(4, 5);
  EXPECT_EQ(d, c & ~3u);
  EXPECT_FALSE(q.is_deleted(d));
  EXPECT_EQ(q.quads(), 3u);
}

}  // namespace
}  // namespace t2
