// Exercise 13b, hidden tests. Oracle: the library's exact test of two segments of T²
// (segment.hpp's `intersects`, which the solution may not call), on every pair of the small
// inputs, and on the answered pair of the large ones, whose answer is known by construction.
// Inputs: back segments drawn over front ones, segments through and on Ω, vertical segments,
// chains meeting only at shared endpoints, three segments through one point (on Ω too),
// collinear overlaps and one-point segments, random small sets on both sides and on Ω, and
// 10⁵ segments where testing every pair takes far longer than the time limit.
#include <gtest/gtest.h>

#include <algorithm>
#include <numeric>
#include <random>
#include <set>
#include <string>

#include <t2/kernel/point.hpp>
#include <t2/kernel/segment.hpp>

#include "meeting.hpp"

namespace {

using t2::Point;

struct Set {
  std::vector<Point> a, b;
  Set& add(const Point& p, const Point& q) {
    a.push_back(p), b.push_back(q);
    return *this;
  }
  bool meet(std::size_t i, std::size_t j) const {
    return t2::intersects(t2::Segment(a[i], b[i]), t2::Segment(a[j], b[j]));
  }
};

Point at(double x, double y) { return Point::cartesian(x, y); }
Point back(double x, double y) { return Point(-1, -x, -y); }  // the back point drawn at (x, y)
Point omega(double x, double y) { return Point::at_infinity(x, y); }

// "" when the answer is right for the set s (brute force over every pair), else what is wrong.
std::string judge(const Set& s) {
  const auto got = ex13b::meeting_pair(s.a, s.b);
  bool any = false;
  for (std::size_t i = 0; i < s.a.size() && !any; ++i)
    for (std::size_t j = i + 1; j < s.a.size() && !any; ++j) any = s.meet(i, j);
  if (!any) return got.empty() ? "" : "no two segments meet";
  if (got.size() != 2 || got[0] < 0 || got[0] >= got[1] || got[1] >= long(s.a.size())) return "expected a pair i < j";
  return s.meet(got[0], got[1]) ? "" : "the two segments answered do not meet";
}

// n diagonal segments from (-4, c - 4) to (4, d + 4), c and d increasing: no two meet.
Set fan(int n, int side) {
  Set s;
  for (int i = 0; i < n; ++i) {
    const double c = i, d = i + 0.25 * (i % 3);
    s.add(Point(side, -side * 4.0, side * (c - 4)), Point(side, side * 4.0, side * (d + 4)));
  }
  return s;
}

TEST(Hidden, BackSide) {
  // A front and a back segment drawn crossing do not meet; two back ones do; a front fan and
  // its copy on the back; a back one-point segment drawn on a front segment.
  EXPECT_EQ(judge(Set().add(at(0, 0), at(4, 4)).add(back(0, 4), back(4, 0))), "");
  EXPECT_EQ(judge(Set().add(back(0, 0), back(4, 4)).add(back(0, 4), back(4, 0))), "");
  Set f = fan(12, 1), g = fan(12, -1);
  for (std::size_t i = 0; i < g.a.size(); ++i) f.add(g.a[i], g.b[i]);
  EXPECT_EQ(judge(f), "");
  f.add(back(0, 6.1), back(0, 6.9));  // crosses the back copy of fan segment 6 only
  EXPECT_EQ(judge(f), "");
  EXPECT_EQ(judge(Set().add(back(1, 1), back(1, 1)).add(at(0, 0), at(4, 4)).add(at(5, 0), at(9, 1))), "");
  EXPECT_EQ(judge(Set().add(Point(-2, -2, -2), Point(-2, -2, -2)).add(back(0, 0), back(4, 4))), "");
}

TEST(Hidden, ThroughAndOnOmega) {
  // Radial segments out to Ω and back from the other side: no two meet (their lines share only
  // the origin and its antipode). Parallel rays meet at Ω. Pieces of Ω. A segment through Ω
  // whose back part is drawn across a front segment, then a back segment on that part.
  Set r;
  for (const auto& [dx, dy] : std::vector<std::pair<int, int>>{{1, 0}, {0, 1}, {1, 1}, {-1, 2}, {-3, 1}, {2, -5}, {-1, -1}})
    r.add(Point(1, 2 * dx, 2 * dy), Point(-1, 2 * dx, 2 * dy));
  EXPECT_EQ(judge(r), "");
  r.add(at(-1, 0), omega(0, 1));
  EXPECT_EQ(judge(r), "");  // meets the radial segment of (0, 1) at Ω
  EXPECT_EQ(judge(Set().add(at(0, 0), omega(0, 1)).add(at(1, 0), omega(0, 1))), "");
  EXPECT_EQ(judge(Set().add(at(0, 0), omega(0, 1)).add(at(1, 0), omega(0, -1))), "");
  Set o = Set().add(omega(1, 0), omega(0, 1)).add(omega(-1, 1), omega(-1, 0));
  EXPECT_EQ(judge(o), "");
  o.add(omega(1, 1), omega(-1, 1));
  EXPECT_EQ(judge(o), "");
  Set t = Set().add(at(0, -2), Point(-1, 0, -2)).add(at(-1, 3), at(1, 3));
  EXPECT_EQ(judge(t), "");
  t.add(back(-1, 3), back(1, 3));
  EXPECT_EQ(judge(t), "");
}

TEST(Hidden, VerticalSegments) {
  // Collinear vertical segments with gaps (on both sides, drawn near the origin and far from
  // it); stacked ones touching; a vertical segment ending on a horizontal one, or crossing a
  // diagonal.
  auto near = [](double x, double y) { return Point(8, x, y); };  // drawn at (x/8, y/8)
  auto near_back = [](double x, double y) { return Point(-8, -x, -y); };
  EXPECT_EQ(judge(Set().add(near(0, 0), near(0, 1)).add(near(0, 3), near(0, 2)).add(near(0, 5), near(0, 4))), "");
  EXPECT_EQ(judge(Set().add(near_back(1, -3), near_back(1, -2)).add(near_back(1, 0), near_back(1, -1)).add(near(1, -1), near(1, -1))), "");
  EXPECT_EQ(judge(Set().add(near(-2, 0), near(-2, 1)).add(near(-2, 1), near(-2, 3)).add(near(3, 3), near(5, 3))), "");
  EXPECT_EQ(judge(Set().add(at(0, 0), at(0, 1)).add(at(0, 3), at(0, 2)).add(at(0, 5), at(0, 4)).add(at(3, -9), at(4, 9))), "");
  EXPECT_EQ(judge(Set().add(back(2, 0), back(2, 1)).add(back(2, 2), back(2, 3)).add(at(2, 1.5), at(2, 1.5))), "");
  EXPECT_EQ(judge(Set().add(at(0, 0), at(0, 1)).add(at(0, 2), at(0, 1))), "");
  EXPECT_EQ(judge(Set().add(at(-5, 0), at(5, 0)).add(at(1, 3), at(1, 0)).add(at(-1, 1), at(-1, 4))), "");
  EXPECT_EQ(judge(Set().add(at(2, -3), at(2, 3)).add(at(0, 0), at(4, 1)).add(at(6, 0), at(6, 8))), "");
}

TEST(Hidden, SharedEndpoints) {
  // x-monotone zigzags meeting only where one segment ends and the next begins, on the front,
  // on the back, and through a point of Ω; and two disjoint triangles.
  Set z, zb;
  for (int i = 0; i < 12; ++i) {
    z.add(at(i, i % 2 ? 3 : 0), at(i + 1, i % 2 ? 0 : 3));
    zb.add(back(i, i % 2 ? 3 : 0), back(i + 1, i % 2 ? 0 : 3));
  }
  EXPECT_EQ(judge(z), "");
  EXPECT_EQ(judge(zb), "");
  EXPECT_EQ(judge(Set().add(at(0, 0), omega(1, 0)).add(omega(1, 0), Point(-1, -5, -1))), "");
  Set tri = Set().add(at(0, 0), at(4, 0)).add(at(4, 0), at(2, 3)).add(at(2, 3), at(0, 0));
  EXPECT_EQ(judge(tri), "");
  EXPECT_EQ(judge(Set().add(at(0, 0), at(4, 0)).add(at(5, 0), at(9, 0)).add(at(2, 1), at(2, 7))), "");
}

TEST(Hidden, ThreeThroughOnePoint) {
  // Three segments crossing at (2, 2); a star through the origin; three parallel rays through
  // Ω meeting only at [0, 1, 1]; three back segments through a back point.
  EXPECT_EQ(judge(Set().add(at(0, 0), at(4, 4)).add(at(0, 4), at(4, 0)).add(at(2, 0), at(2, 5)).add(at(7, 7), at(9, 9))), "");
  Set star;
  for (int k = 0; k < 8; ++k) star.add(at(-1 - k, 2 * k - 7), at(1 + k, 7 - 2 * k));
  EXPECT_EQ(judge(star), "");
  Set par;
  for (int k = 0; k < 3; ++k) par.add(at(3 * k, -3 * k), Point(-1, -3 * k - 6, 3 * k - 6));
  EXPECT_EQ(judge(par), "");
  EXPECT_EQ(judge(Set().add(back(0, 0), back(4, 4)).add(back(0, 4), back(4, 0)).add(back(2, 0), back(2, 4)).add(at(2, 2), at(3, 2))), "");
}

TEST(Hidden, OverlapsAndPoints) {
  // Collinear overlaps and gaps, equal segments, one-point segments on and off a segment, and
  // two collinear segments overlapping only next to Ω (one goes through it).
  EXPECT_EQ(judge(Set().add(at(0, 0), at(4, 4)).add(at(6, 6), at(2, 2))), "");
  EXPECT_EQ(judge(Set().add(at(0, 0), at(1, 1)).add(at(2, 2), at(3, 3)).add(at(4, 4), at(5, 5))), "");
  EXPECT_EQ(judge(Set().add(at(1, 2), at(3, 5)).add(at(3, 5), at(1, 2))), "");
  EXPECT_EQ(judge(Set().add(at(1, 1), at(1, 1)).add(Point(3, 3, 3), Point(3, 3, 3))), "");
  EXPECT_EQ(judge(Set().add(at(0, 0), at(4, 2)).add(at(2, 1), at(2, 1))), "");
  EXPECT_EQ(judge(Set().add(at(0, 0), at(4, 2)).add(at(3, 1), at(3, 1))), "");
  EXPECT_EQ(judge(Set().add(at(0, 0), Point(-1, 0, 5)).add(at(0, 5), omega(0, 1))), "");
  EXPECT_EQ(judge(Set().add(at(0, 0), at(0, 4)).add(back(0, 1), back(0, 3))), "");
}

TEST(Hidden, RandomAgainstBruteForce) {
  // Small integer coordinates (many collinear and shared points), w in {-2, ..., 2}.
  std::mt19937_64 g(1331);
  auto pick = [&] {
    for (;;) {
      const double w = double(int(g() % 5) - 2), x = double(int(g() % 7) - 3), y = double(int(g() % 7) - 3);
      if (w != 0 || x != 0 || y != 0) return Point(w, x, y);
    }
  };
  int bad = 0;
  for (int k = 0; k < 1500 && bad < 3; ++k) {
    Set s;
    const int n = 2 + int(g() % 8);
    while (int(s.a.size()) < n) {
      const Point p = pick(), q = g() % 8 == 0 ? p : pick();
      if (q != t2::antipode(p)) s.add(p, q);
    }
    const std::string e = judge(s);
    EXPECT_EQ(e, "");
    bad += !e.empty();
  }
}

// The large input: n front diagonal segments that do not meet (all their x- and y-ranges
// overlap, so no bounding box separates two of them), the same drawings on the back side, and
// m radial segments out to Ω and back; with `one`, a short back segment crossing back fan
// segment n/2 only. Shuffled, ends swapped at random; hit gets the indices of the two that meet.
Set large(std::mt19937_64& g, int n, int m, bool one, std::vector<long>& hit) {
  const double W = 2097152, L = 1048576;
  Set s;
  for (const int side : {1, -1})
    for (int i = 0; i < n; ++i) {
      const double c = 20.0 * i, d = 20.0 * i + 3 * (i % 5);
      s.add(Point(side * W, -side * L, side * (c - L)), Point(side * W, side * L, side * (d + L)));
    }
  std::set<std::pair<int, int>> used;
  while (int(used.size()) < m) {  // distinct primitive directions, no two opposite
    const int dx = int(g() % 401) - 200, dy = int(g() % 401) - 200;
    if (std::gcd(dx, dy) != 1 || used.count({-dx, -dy}) || !used.insert({dx, dy}).second) continue;
    s.add(Point(1, 2 * dx, 2 * dy), Point(-1, 2 * dx, 2 * dy));  // radius ≥ 2: outside the fans
  }
  if (one) {
    const double y = 20.0 * (n / 2) + 1.5 * ((n / 2) % 5);  // fan segment n/2 at x = 0
    s.add(Point(-W, 0, -(y - 5)), Point(-W, 0, -(y + 5)));
  }
  std::vector<std::size_t> order(s.a.size());
  std::iota(order.begin(), order.end(), 0);
  std::shuffle(order.begin(), order.end(), g);
  Set r;
  for (std::size_t k = 0; k < order.size(); ++k) {
    const bool swap = g() % 2;
    r.add(swap ? s.b[order[k]] : s.a[order[k]], swap ? s.a[order[k]] : s.b[order[k]]);
    if (order[k] == std::size_t(n + n / 2) || order[k] == std::size_t(2 * n + m)) hit.push_back(long(k));
  }
  return r;
}

TEST(Hidden, LargeNoMeeting) {
  std::mt19937_64 g(1332);
  std::vector<long> hit;
  const Set s = large(g, 40000, 20000, false, hit);
  EXPECT_TRUE(ex13b::meeting_pair(s.a, s.b).empty());
}

TEST(Hidden, LargeOneMeeting) {
  std::mt19937_64 g(1333);
  std::vector<long> hit;
  const Set s = large(g, 40000, 20000, true, hit);
  ASSERT_EQ(hit.size(), 2u);
  EXPECT_EQ(ex13b::meeting_pair(s.a, s.b), hit);
}

}  // namespace
