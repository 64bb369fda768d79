// `--scene OUT` of the algorithm commands (tools/t2/model_picture.hpp): the written file is a
// valid scene, holds the command's answer (checked against what the command printed and the
// input's points), and `t2 draw INPUT OUT` composes them into the very picture `--svg` draws.
#include <set>
#include <sstream>

#include "cli_testing.hpp"
#include "t2/kernel/scene.hpp"

namespace t2::testing {
namespace {

class AnswerScene : public CliTest {
 protected:
  // Runs `command`, which must write a.t2 and a.svg; checks the composition and returns the
  // stdout and the answer scene.
  std::pair<std::string, Scene> run(const std::string& command, const std::string& input) {
    const Result r = t2(command + " --scene a.t2 --svg a.svg --model plane");
    EXPECT_EQ(r.status, 0) << r.err;
    const Scene answer = parse_scene(slurp(dir_ / "a.t2"), "a.t2");  // throws when not a scene
    EXPECT_TRUE(slurp(dir_ / "a.t2").starts_with("# t2 ")) << slurp(dir_ / "a.t2");
    const Result d = t2("draw " + input + " a.t2 --model plane -o composed.svg");
    EXPECT_EQ(d.status, 0) << d.err;
    EXPECT_EQ(slurp(dir_ / "composed.svg"), slurp(dir_ / "a.svg")) << command;
    return {r.out, answer};
  }
  std::vector<Point> points(const std::string& file) {
    std::vector<Point> P;
    for (const auto& p : read_scene(dir_ / file).points) P.push_back(p.point);
    return P;
  }
};

std::vector<std::vector<std::size_t>> rows(const std::string& out) {
  std::vector<std::vector<std::size_t>> v;
  std::istringstream in(out);
  for (std::string line; std::getline(in, line);) {
    std::istringstream words(line);
    std::vector<std::size_t> row;
    for (std::size_t i; words >> i;) row.push_back(i);
    v.push_back(row);
  }
  return v;
}

TEST_F(AnswerScene, HullPolygonIsTheHullOfTheIndices) {
  ASSERT_EQ(t2("gen both-sides --n 40 --seed 9 -o pts.t2").status, 0);
  const auto [out, answer] = run("hull pts.t2", "pts.t2");
  const auto P = points("pts.t2");
  std::vector<std::size_t> h;
  for (const auto& r : rows(out)) h.push_back(r.at(0));
  ASSERT_EQ(answer.polygons.size(), 1u);
  const auto& poly = answer.polygons[0];
  ASSERT_EQ(poly.vertices.size(), h.size());
  ASSERT_EQ(answer.points.size(), h.size());
  for (std::size_t k = 0; k < h.size(); ++k) {
    EXPECT_EQ(poly.vertices[k].point, P[h[k]]) << k;
    EXPECT_EQ(answer.points[k].point, P[h[k]]);
    EXPECT_EQ(answer.points[k].style.label, "p" + std::to_string(h[k]));
  }
  EXPECT_EQ(poly.style.color, "#2ca02c");
  // Two points: the hull is a segment.
  write("two.t2", "0 0\n1 1\n");
  const auto [o2, a2] = run("hull two.t2", "two.t2");
  ASSERT_EQ(a2.segments.size(), 1u);
  EXPECT_TRUE(a2.polygons.empty());
}

TEST_F(AnswerScene, LayersOnePolygonPerLine) {
  ASSERT_EQ(t2("gen uniform --n 40 --seed 4 -o pts.t2").status, 0);
  const auto [out, answer] = run("layers pts.t2", "pts.t2");
  const auto P = points("pts.t2");
  const auto L = rows(out);
  std::size_t polygons = 0, segments = 0, single = 0;
  for (std::size_t j = 0; j < L.size(); ++j) {
    if (L[j].size() >= 3) {
      const auto& g = answer.polygons.at(polygons++);
      ASSERT_EQ(g.vertices.size(), L[j].size());
      for (std::size_t k = 0; k < L[j].size(); ++k) EXPECT_EQ(g.vertices[k].point, P[L[j][k]]);
      EXPECT_EQ(g.style.label, "L" + std::to_string(j + 1));
    } else if (L[j].size() == 2) {
      EXPECT_EQ(answer.segments.at(segments++).a.point, P[L[j][0]]);
    } else {
      EXPECT_EQ(answer.points.at(single++).point, P[L[j][0]]);
    }
  }
  EXPECT_EQ(polygons, answer.polygons.size());
  EXPECT_EQ(segments, answer.segments.size());
  EXPECT_GE(L.size(), 3u);
}

// A triangle a b c, whatever vertex it starts at: its least rotation, written out.
std::string key(const Point& a, const Point& b, const Point& c) {
  const std::string s[] = {to_string(a), to_string(b), to_string(c)};
  return std::min({s[0] + s[1] + s[2], s[1] + s[2] + s[0], s[2] + s[0] + s[1]});
}

TEST_F(AnswerScene, TrianglesAreTheListedTriangles) {
  ASSERT_EQ(t2("gen uniform --n 25 --seed 2 -o pts.t2").status, 0);
  const auto P = points("pts.t2");
  for (const char* c : {"triangulate", "delaunay"}) {
    const auto [out, answer] = run(std::string(c) + " pts.t2", "pts.t2");
    std::set<std::string> listed, drawn;
    for (const auto& t : rows(out)) listed.insert(key(P[t.at(0)], P[t.at(1)], P[t.at(2)]));
    for (const auto& g : answer.polygons)
      drawn.insert(key(g.vertices.at(0).point, g.vertices.at(1).point, g.vertices.at(2).point));
    EXPECT_EQ(drawn, listed) << c;
    EXPECT_EQ(answer.points.size(), P.size());  // the labels pK
  }
}

TEST_F(AnswerScene, DiameterPairAndKernelPolygon) {
  write("d.t2", "0 0\n4 0\n4 1\n1 2\n");
  const auto [out, answer] = run("diameter d.t2", "d.t2");
  const auto P = points("d.t2");
  const auto pair = rows(out).at(0);
  ASSERT_EQ(answer.segments.size(), 1u);
  EXPECT_EQ(answer.segments[0].a.point, P[pair.at(0)]);
  EXPECT_EQ(answer.segments[0].b.point, P[pair.at(1)]);
  EXPECT_EQ(answer.lines.size(), 2u);  // the narrowest strip
  // An L-shaped polygon: its kernel is the corner square, corners as printed.
  write("k.t2", "polygon\n0 0\n2 0\n2 1\n1 1\n1 2\n0 2\nend\n");
  const auto [kout, kernel] = run("kernel k.t2", "k.t2");
  ASSERT_EQ(kernel.polygons.size(), 1u);
  std::istringstream in(kout);
  std::string kind;
  in >> kind;
  EXPECT_EQ(kind, "bounded");
  for (const auto& v : kernel.polygons[0].vertices) {
    double w, x, y;
    ASSERT_TRUE(in >> w >> x >> y);
    EXPECT_EQ(v.point, Point(w, x, y));
  }
}

TEST_F(AnswerScene, NothingWrittenOnBadInputAndDrawNamesTheBadFile) {
  write("bad.t2", "0 0\nsegment\n");
  EXPECT_EQ(t2("hull bad.t2 --scene a.t2").status, 2);
  EXPECT_FALSE(fs::exists(dir_ / "a.t2"));
  write("ok.t2", "0 0\n1 0\n0 1\n");
  const Result r = t2("draw ok.t2 bad.t2 -o x.svg");
  EXPECT_EQ(r.status, 2);
  EXPECT_TRUE(has(r.err, "bad.t2:2:")) << r.err;
  EXPECT_FALSE(fs::exists(dir_ / "x.svg"));
}

}  // namespace
}  // namespace t2::testing
