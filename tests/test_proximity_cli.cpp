// t2 emst, t2 ann and t2 closest-pair from the command line: the documented 'i j' lines equal
// the library's answer on random input of both sides, the three closest-pair algorithms agree, the
// exit statuses of bad and undefined input (file:line), and the answer scene.
#include <fmt/format.h>

#include <random>
#include <sstream>

#include "cli_testing.hpp"
#include "t2/proximity/closest_pair.hpp"
#include "t2/proximity/nearest_neighbors.hpp"
#include "t2/proximity/spanning_tree.hpp"

namespace t2::testing {
namespace {

class ProximityCli : public CliTest {};

bool has(const std::string& s, const std::string& what) { return s.find(what) != std::string::npos; }

std::string lines(const std::vector<std::pair<std::uint32_t, std::uint32_t>>& pairs) {
  std::string s;
  for (auto [i, j] : pairs) s += fmt::format("{} {}\n", i, j);
  return s;
}

TEST_F(ProximityCli, PrintsTheLibrarysAnswer) {
  std::mt19937 rng(7);
  std::uniform_int_distribution<int> c(-20, 20), side(0, 3);
  std::vector<Point> P;
  std::string file;
  for (int k = 0; k < 60; ++k) {
    const int w = side(rng) == 0 ? -1 : 1, x = c(rng), y = c(rng);
    P.emplace_back(w, x, y);
    file += fmt::format("{} {} {}\n", w, x, y);
  }
  write("p.t2", file);
  const Result e = t2("emst p.t2");
  ASSERT_EQ(e.status, 0) << e.err;
  EXPECT_EQ(e.out, lines(minimum_spanning_tree(P)));
  const Result a = t2("ann p.t2");
  ASSERT_EQ(a.status, 0) << a.err;
  std::vector<std::pair<std::uint32_t, std::uint32_t>> nn;
  const auto near = all_nearest_neighbors(P);
  for (std::uint32_t i = 0; i < near.size(); ++i) nn.emplace_back(i, near[i]);
  EXPECT_EQ(a.out, lines(nn));
  const Result b = t2("closest-pair p.t2 --algorithm brute"), d = t2("closest-pair p.t2");
  ASSERT_EQ(b.status, 0) << b.err;
  ASSERT_EQ(d.status, 0) << d.err;
  EXPECT_EQ(b.out, d.out);
  EXPECT_EQ(d.out, lines({closest_pair_brute(P)}));
  const Result v = t2("closest-pair p.t2 --algorithm divide");
  ASSERT_EQ(v.status, 0) << v.err;
  EXPECT_EQ(v.out, d.out);
}

TEST_F(ProximityCli, SmallCasesByHand) {
  write("sq.t2", "0 0\n2 0\n0 1\n2 1\n");  // a 2 x 1 rectangle: the short sides
  EXPECT_EQ(t2("closest-pair sq.t2").out, "0 2\n");
  EXPECT_EQ(t2("closest-pair sq.t2 --algorithm divide").out, "0 2\n");
  EXPECT_EQ(t2("emst sq.t2").out, "0 2\n1 3\n0 1\n");
  EXPECT_EQ(t2("ann sq.t2").out, "0 2\n1 3\n2 0\n3 1\n");
  write("eq.t2", "1 1\n5 5\n2 2 2\n");  // p2 equals p0
  EXPECT_EQ(t2("closest-pair eq.t2").out, "0 2\n");
}

TEST_F(ProximityCli, BadAndUndefinedInput) {
  write("bad.t2", "0 0\n1 x\n");
  for (const char* cmd : {"emst", "ann", "closest-pair"}) {
    const Result r = t2(std::string(cmd) + " bad.t2");
    EXPECT_EQ(r.status, 2) << cmd;
    EXPECT_TRUE(has(r.err, "bad.t2:2")) << cmd << ": " << r.err;
  }
  write("one.t2", "0 0\n");
  EXPECT_EQ(t2("closest-pair one.t2").status, 2);
  EXPECT_EQ(t2("ann one.t2").status, 2);
  EXPECT_EQ(t2("emst one.t2").out, "");
  EXPECT_EQ(t2("closest-pair one.t2 --algorithm divide").status, 2);
  // A point of Omega between a front and a back point: its nearest is undefined (line 4).
  write("omega.t2", "0 0\n1 0\n-1 0 0\n0 1 0\n");
  const Result u = t2("ann omega.t2");
  EXPECT_EQ(u.status, 3);
  EXPECT_TRUE(has(u.err, "omega.t2:4:")) << u.err;
  EXPECT_TRUE(u.out.empty());
  EXPECT_EQ(t2("emst omega.t2").status, 0);  // the tree is defined there
}

TEST_F(ProximityCli, WritesTheAnswerScene) {
  write("tri.t2", "0 0\n4 0\n0 3\n");
  const Result r = t2("emst tri.t2 --svg tree.svg --scene tree.scene");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_TRUE(has(slurp(dir_ / "tree.svg"), "<svg"));
  const std::string scene = slurp(dir_ / "tree.scene");
  EXPECT_TRUE(has(scene, "t2 emst tri.t2")) << scene;
  std::size_t segments = 0;  // the tree of three points: two segments
  for (std::size_t at = scene.find("segment"); at != std::string::npos; at = scene.find("segment", at + 1)) ++segments;
  EXPECT_EQ(segments, 2u) << scene;
}

}  // namespace
}  // namespace t2::testing
