// The largest empty circle with a proper centre (t2/proximity/empty_circle.hpp) against an
// oracle written from the definition on exact rationals: every circumcentre of three sites in
// the hull and every crossing of the bisector of two sites with a hull edge, each with its true
// radius (the least distance to every site), at small n on front and back sites with
// duplicates, lattice ties, collinear and cocircular sites; at larger n, certificates (no site
// strictly inside, centre in the hull, no sampled point of the hull a larger empty centre);
// the undefined inputs, and `t2 lec`.
#include <optional>
#include <random>

#include "cli_testing.hpp"
#include "oracle.hpp"
#include "t2/proximity/empty_circle.hpp"
#include "testing.hpp"

namespace t2::testing {
namespace {

using Index = EmptyCircle::Index;

Rational cross(const Pos& o, const Pos& a, const Pos& b) {
  return (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0]);
}

/// The supporting pairs (i, j): every site left of i → j or on its line; z is in the closed
/// hull when it is left of or on every one of them (all pairs when the sites are collinear).
struct BruteHull {
  std::vector<Pos> X;
  std::vector<std::pair<int, int>> support;
  explicit BruteHull(const std::vector<Pos>& X) : X(X) {
    for (std::size_t i = 0; i < X.size(); ++i)
      for (std::size_t j = 0; j < X.size(); ++j) {
        if (X[i] == X[j]) continue;
        bool all = true;
        for (const Pos& s : X) all = all && cross(X[i], X[j], s) >= 0;
        if (all) support.emplace_back(i, j);
      }
  }
  bool holds(const Pos& z) const {
    for (auto [i, j] : support)
      if (cross(X[i], X[j], z) < 0) return false;
    return true;
  }
};

/// The true radius of the empty circle centred at z: the least squared distance to a site.
Rational radius2(const std::vector<Pos>& X, const Pos& z) {
  Rational r = sq(X[0], z);
  for (const Pos& s : X) r = std::min(r, sq(s, z));
  return r;
}

/// The answer from the definition: the best of every candidate, largest radius, then smallest
/// (x, y).
std::pair<Pos, Rational> brute(const std::vector<Pos>& X) {
  const BruteHull hull(X);
  std::optional<std::pair<Pos, Rational>> best;
  auto offer = [&](const Pos& z) {
    const Rational r = radius2(X, z);
    if (!best || r > best->second || (r == best->second && z < best->first)) best = {z, r};
  };
  const std::size_t n = X.size();
  for (std::size_t a = 0; a < n; ++a)
    for (std::size_t b = a + 1; b < n; ++b)
      for (std::size_t c = b + 1; c < n; ++c) {
        const Rational bx = X[b][0] - X[a][0], by = X[b][1] - X[a][1], cx = X[c][0] - X[a][0], cy = X[c][1] - X[a][1];
        const Rational D = 2 * (bx * cy - by * cx);
        if (D == 0) continue;
        const Rational b2 = bx * bx + by * by, c2 = cx * cx + cy * cy;
        const Pos z{Rational(X[a][0] + (cy * b2 - by * c2) / D), Rational(X[a][1] + (bx * c2 - cx * b2) / D)};
        if (hull.holds(z)) offer(z);
      }
  for (auto [k, l] : hull.support)  // the hull edge k → l, λ in [0, 1]
    for (std::size_t s = 0; s < n; ++s)
      for (std::size_t t = s + 1; t < n; ++t) {
        const Pos D{Rational(X[l][0] - X[k][0]), Rational(X[l][1] - X[k][1])};
        const Rational den = 2 * (D[0] * (X[t][0] - X[s][0]) + D[1] * (X[t][1] - X[s][1]));
        if (den == 0) continue;
        const Rational lambda = (sq(X[t], X[k]) - sq(X[s], X[k])) / den;
        if (lambda < 0 || lambda > 1) continue;
        offer(Pos{Rational(X[k][0] + lambda * D[0]), Rational(X[k][1] + lambda * D[1])});
      }
  return *best;
}

std::vector<Pos> drawn(const std::vector<Point>& P) {
  std::vector<Pos> X;
  for (const Point& p : P) X.push_back(pos(p));
  return X;
}

Pos centre(const EmptyCircle& c) { return pos(std::array<Integer, 3>{c.center.w(), c.center.x(), c.center.y()}); }

/// What every answer must satisfy, whatever the oracle: W of the sites' sign, no common factor,
/// the radius that of a site on the circle, no site strictly inside, the list of sites on it.
void check_answer(const std::vector<Point>& P, const EmptyCircle& c) {
  const std::vector<Pos> X = drawn(P);
  const Pos z = centre(c);
  EXPECT_EQ(sgn(c.center.w()), P[0].w() > 0 ? 1 : -1);
  Integer g;
  mpz_gcd(g.get_mpz_t(), c.center.w().get_mpz_t(), c.center.x().get_mpz_t());
  mpz_gcd(g.get_mpz_t(), g.get_mpz_t(), c.center.y().get_mpz_t());
  EXPECT_EQ(g, 1);
  EXPECT_EQ(radius2(X, z), c.radius2);
  std::vector<Index> on;
  for (Index k = 0; k < X.size(); ++k)
    if (sq(X[k], z) == c.radius2) on.push_back(k);
  EXPECT_EQ(c.on_circle, on);
}

/// Small random sites of one side: lattice ties, repeats (some at another scale), w ∈ {1, 2}.
std::vector<Point> small_sites(std::mt19937& rng, int n, int range, int side) {
  std::uniform_int_distribution<int> c(-range, range), coin(0, 9);
  std::vector<Point> P;
  while (static_cast<int>(P.size()) < n) {
    if (!P.empty() && coin(rng) == 0) {
      const Point q = P[std::uniform_int_distribution<std::size_t>(0, P.size() - 1)(rng)];
      P.emplace_back(2 * q.w(), 2 * q.x(), 2 * q.y());
      continue;
    }
    const double w = side * (coin(rng) < 3 ? 2 : 1);
    P.emplace_back(w, c(rng), c(rng));
  }
  return P;
}

TEST(EmptyCircle, AgreesWithTheOracleOnSmallSites) {
  int defined = 0;
  for (int seed = 0; seed < 150 * scale(); ++seed) {
    std::mt19937 rng(seed);
    const int side = seed % 3 == 2 ? -1 : 1;
    const std::vector<Point> P = small_sites(rng, 2 + seed % 11, 1 + seed % 6, side);
    SCOPED_TRACE("seed " + std::to_string(seed));
    const std::vector<Pos> X = drawn(P);
    if (std::all_of(X.begin(), X.end(), [&](const Pos& p) { return p == X[0]; })) {
      EXPECT_THROW(largest_empty_circle(P), UndefinedEmptyCircle);
      continue;
    }
    const EmptyCircle c = largest_empty_circle(P);
    check_answer(P, c);
    // The back answer is the antipode of the mirrored problem's: ¬s is drawn where s is, and
    // the antipode of the centre too, so the oracle answers on the drawn positions.
    const auto [z, r] = brute(X);
    EXPECT_EQ(centre(c), z);
    EXPECT_EQ(c.radius2, r);
    ++defined;
  }
  EXPECT_GT(defined, 100 * scale());
}

TEST(EmptyCircle, ThinTrianglesAgreeWithTheOracle) {
  // Sites near a parabola and a few off it: nearly collinear triangles with huge circumcircles,
  // where the double bound of the radius gives up or is loose; its pruning must keep the best.
  for (int seed = 0; seed < 30 * scale(); ++seed) {
    std::mt19937 rng(500 + seed);
    std::uniform_real_distribution<double> u(-1, 1);
    std::vector<Point> P;
    for (int k = 0; k < 9; ++k) {
      const double x = u(rng);
      P.emplace_back(1, x, 0x1p-30 * x * x + (seed % 3 == 0 ? 0x1p-60 * u(rng) : 0));
    }
    for (int k = 0; k < 1 + seed % 3; ++k) P.emplace_back(1, u(rng), u(rng) * 0x1p-20);
    SCOPED_TRACE("seed " + std::to_string(seed));
    const EmptyCircle c = largest_empty_circle(P);
    check_answer(P, c);
    const auto [z, r] = brute(drawn(P));
    EXPECT_EQ(centre(c), z);
    EXPECT_EQ(c.radius2, r);
  }
}

TEST(EmptyCircle, LatticeTiesBetweenVoronoiVertices) {
  // Subsets of a 5 x 5 lattice, w = 1: many Voronoi vertices of one radius, which the tie rule
  // orders by position; the double bound must let every one of them be compared.
  for (int seed = 0; seed < 60 * scale(); ++seed) {
    std::mt19937 rng(900 + seed);
    std::vector<Point> P;
    for (int k = 0; k < 25; ++k)
      if (std::uniform_int_distribution<int>(0, 9)(rng) < 6) P.emplace_back(1, k % 5, k / 5);
    if (P.size() < 3) continue;
    SCOPED_TRACE("seed " + std::to_string(seed));
    const std::vector<Pos> X = drawn(P);
    bool collinear = true;
    for (const Pos& p : X) collinear = collinear && cross(X[0], X[1], p) == 0;
    if (collinear) continue;
    const EmptyCircle c = largest_empty_circle(P);
    const auto [z, r] = brute(X);
    EXPECT_EQ(centre(c), z);
    EXPECT_EQ(c.radius2, r);
  }
}

TEST(EmptyCircle, CollinearAndCocircularByHand) {
  // Collinear: the widest gap, 1 → 5, halved.
  EmptyCircle c = largest_empty_circle(std::vector<Point>{{1, 0, 0}, {1, 1, 0}, {1, 5, 0}, {2, 0, 0}});
  EXPECT_EQ(c.center, ExactPoint(Integer(1), Integer(3), Integer(0)));
  EXPECT_EQ(c.radius2, 4);
  EXPECT_EQ(c.on_circle, (std::vector<Index>{1, 2}));
  // A square and its centre: four centres of radius 2 on the hull, the smallest (0, 2) wins.
  c = largest_empty_circle(std::vector<Point>{{1, 0, 0}, {1, 4, 0}, {1, 0, 4}, {1, 4, 4}, {1, 2, 2}});
  EXPECT_EQ(c.center, ExactPoint(Integer(1), Integer(0), Integer(2)));
  EXPECT_EQ(c.on_circle, (std::vector<Index>{0, 2, 4}));
  // A regular-ish polygon with an empty middle: the centre of its circle.
  std::vector<Point> ring;
  const int pyth[][2] = {{5, 0}, {4, 3}, {3, 4}, {0, 5}, {-3, 4}, {-4, 3}, {-5, 0}, {-4, -3}, {-3, -4}, {0, -5}, {3, -4}, {4, -3}};
  for (auto [x, y] : pyth) ring.emplace_back(1, x + 7, y - 2);
  c = largest_empty_circle(ring);
  EXPECT_EQ(c.center, ExactPoint(Integer(1), Integer(7), Integer(-2)));
  EXPECT_EQ(c.radius2, 25);
  EXPECT_EQ(c.on_circle.size(), 12u);
}

TEST(EmptyCircle, CertificatesAtLargerN) {
  for (int seed = 0; seed < 2 * scale(); ++seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> u(-1, 1);
    std::vector<Point> P;
    for (int k = 0; k < 400; ++k) P.emplace_back(seed == 1 ? -1 : 1, u(rng), u(rng) * (1 - u(rng) * u(rng)));
    const EmptyCircle c = largest_empty_circle(P);
    check_answer(P, c);
    std::vector<Pos> X = drawn(P);
    const BruteHull hull(X);
    EXPECT_TRUE(hull.holds(centre(c)));
    EXPECT_GE(c.on_circle.size(), 2u);
    // No point of the hull sampled (convex combinations of sites) is a larger empty centre.
    std::uniform_int_distribution<std::size_t> pick(0, X.size() - 1);
    for (int k = 0; k < 300; ++k) {
      const Pos& a = X[pick(rng)];
      const Pos& b = X[pick(rng)];
      const Pos& d = X[pick(rng)];
      const Pos z{Rational((a[0] + b[0] + d[0]) / 3), Rational((a[1] + b[1] + d[1]) / 3)};
      EXPECT_LE(radius2(X, z), c.radius2);
    }
  }
}

TEST(EmptyCircle, UndefinedInputs) {
  EXPECT_THROW(largest_empty_circle(std::vector<Point>{}), BadInput);
  EXPECT_THROW(largest_empty_circle(std::vector<Point>{{1, 1, 1}, {2, 2, 2}}), UndefinedEmptyCircle);
  try {
    largest_empty_circle(std::vector<Point>{{1, 0, 0}, {1, 1, 0}, {1, 0, 1}, {-1, 3, 3}});
    ADD_FAILURE() << "sites on both sides";
  } catch (const UndefinedEmptyCircle& e) {
    EXPECT_EQ(e.site, 0u);
    EXPECT_EQ(e.other, 3u);
  }
  try {
    largest_empty_circle(std::vector<Point>{{1, 0, 0}, {1, 1, 0}, {0, 0, 1}});
    ADD_FAILURE() << "a site on Omega";
  } catch (const UndefinedEmptyCircle& e) {
    EXPECT_EQ(e.site, 2u);
    EXPECT_EQ(e.other, 2u);
  }
}

class EmptyCircleCli : public CliTest {};

TEST_F(EmptyCircleCli, PrintsTheCentreAndTheSitesOnTheCircle) {
  write("p.t2", "0 0\n4 0\n# a comment\n0 4\n4 4\n");
  Result r = t2("lec p.t2");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.out, "1 2 2\n0 1 2 3\n");
  write("b.t2", "-1 0 0\n-1 4 0\n-1 0 4\n-1 4 4\n");
  r = t2("lec b.t2");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.out, "-1 2 2\n0 1 2 3\n");  // drawn centre (-2, -2), on the back
  write("c.t2", "0 0\n2 1 0\n5 0\n");
  r = t2("lec c.t2");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.out, "4 11 0\n1 2\n");  // collinear: the widest gap, 1/2 to 5, its midpoint 11/4
  write("o.t2", "0 0\n1 0\n0 1 1\n");
  r = t2("lec o.t2");
  EXPECT_EQ(r.status, 3);
  EXPECT_NE(r.err.find("o.t2:3"), std::string::npos) << r.err;
  write("m.t2", "0 0\n-1 1 0\n");
  r = t2("lec m.t2");
  EXPECT_EQ(r.status, 3);
  EXPECT_NE(r.err.find("m.t2:1 and line 2"), std::string::npos) << r.err;
  write("q.t2", "1 1\n2 2 2\n");
  EXPECT_EQ(t2("lec q.t2").status, 3);
  write("e.t2", "# nothing\n");
  EXPECT_EQ(t2("lec e.t2").status, 2);
  write("x.t2", "0 0\n1 x\n");
  r = t2("lec x.t2");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("x.t2:2"), std::string::npos) << r.err;
  r = t2("lec p.t2 --scene s.t2 --svg s.svg");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(slurp(dir_ / "s.t2").find("circle"), std::string::npos);
}

}  // namespace
}  // namespace t2::testing
