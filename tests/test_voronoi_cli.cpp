// t2 voronoi from the command line: the format of the README (vertex, edge, ray, line), the
// library's answer on generated input (the dual, and Fortune's front half), cocircular points,
// the exit statuses of bad and undefined input, and the picture.
#include <algorithm>
#include <filesystem>
#include <sstream>

#include "cli_testing.hpp"
#include "t2/kernel/scene.hpp"
#include "t2/voronoi/fortune.hpp"
#include "t2/voronoi/voronoi.hpp"

namespace t2::testing {
namespace {

struct Parsed {
  std::vector<std::string> coords;           // "W X Y" of each vertex
  std::vector<std::vector<int>> sites;       // the sites of each vertex
  std::vector<std::array<int, 4>> edges;     // A B s t
  std::vector<std::pair<int, int>> lines;    // s t
  std::vector<std::string> rays;             // "A  0 X Y  s t" as printed
};

Parsed parse(const std::string& out) {
  Parsed p;
  std::istringstream in(out);
  std::string line;
  while (std::getline(in, line)) {
    std::istringstream l(line);
    std::string kind;
    l >> kind;
    if (kind == "vertex") {
      std::string w, x, y;
      l >> w >> x >> y;
      p.coords.push_back(w + " " + x + " " + y);
      std::vector<int> s;
      for (int k; l >> k;) s.push_back(k);
      p.sites.push_back(s);
    } else if (kind == "edge") {
      std::array<int, 4> e{};
      l >> e[0] >> e[1] >> e[2] >> e[3];
      p.edges.push_back(e);
    } else if (kind == "line") {
      std::pair<int, int> s;
      l >> s.first >> s.second;
      p.lines.push_back(s);
    } else if (kind == "ray") {
      p.rays.push_back(line.substr(4));
    } else {
      ADD_FAILURE() << "unknown line: " << line;
    }
  }
  return p;
}

/// The exact point of a "W X Y" of the output.
ExactPoint exact_of(const std::string& coords) {
  std::istringstream c(coords);
  std::string w, x, y;
  c >> w >> x >> y;
  return ExactPoint(Integer(w), Integer(x), Integer(y));
}

/// The points of a scene file.
std::vector<Point> points_of(const std::filesystem::path& file) {
  std::vector<Point> pts;
  for (const ScenePoint& q : read_scene(file).points) pts.push_back(q.point);
  return pts;
}

/// v rotated to start at its smallest element.
std::vector<int> rotated(std::vector<int> v) {
  std::rotate(v.begin(), std::min_element(v.begin(), v.end()), v.end());
  return v;
}

class VoronoiCli : public CliTest {
 protected:
  /// `t2 voronoi` with `options` on 300 generated points (put in `pts`): its parsed output.
  Parsed generated(const std::string& options, std::vector<Point>& pts) {
    EXPECT_EQ(t2("gen uniform --n 300 --seed 7 -o pts.t2").status, 0);
    const Result r = t2("voronoi pts.t2" + options);
    EXPECT_EQ(r.status, 0) << r.err;
    pts = points_of(dir_ / "pts.t2");
    return parse(r.out);
  }
};

TEST_F(VoronoiCli, CocircularSquareHasOneVertexEachSide) {
  write("sq.t2", "1 0\n0 1\n-1 0\n0 -1\n");
  const Result r = t2("voronoi sq.t2");
  ASSERT_EQ(r.status, 0) << r.err;
  const Parsed p = parse(r.out);
  ASSERT_EQ(p.coords.size(), 2u) << r.out;
  for (std::size_t v = 0; v < 2; ++v) {  // the centre in front, counter-clockwise; behind, mirrored
    if (p.coords[v] == "1 0 0") {
      EXPECT_EQ(rotated(p.sites[v]), (std::vector<int>{0, 1, 2, 3}));
    } else {
      EXPECT_EQ(p.coords[v], "-1 0 0");
      EXPECT_EQ(rotated(p.sites[v]), (std::vector<int>{0, 3, 2, 1}));
    }
  }
  EXPECT_EQ(p.edges.size(), 4u);
  for (const auto& e : p.edges) EXPECT_NE(e[0], e[1]);
}

TEST_F(VoronoiCli, EqualsTheLibrary) {
  std::vector<Point> pts;
  const Parsed p = generated("", pts);
  const VoronoiDiagram vd = voronoi(pts);
  ASSERT_EQ(p.coords.size(), vd.size());
  ASSERT_EQ(p.edges.size(), vd.edges.size());
  for (VoronoiDiagram::Index v = 0; v < vd.size(); ++v) {
    EXPECT_EQ(exact_of(p.coords[v]), vd.vertex(v));
    EXPECT_EQ(p.sites[v], std::vector<int>(vd.vertex_sites(v).begin(), vd.vertex_sites(v).end()));
  }
  for (std::size_t e = 0; e < vd.edges.size(); ++e)
    EXPECT_EQ(p.edges[e], (std::array<int, 4>{int(vd.edges[e].a), int(vd.edges[e].b), int(vd.edges[e].s),
                                              int(vd.edges[e].t)}));
}

TEST_F(VoronoiCli, TwoPointsGiveALineAndDuplicatesAreNamed) {
  write("two.t2", "0 0\n3 1\n0 0\n");
  const Result r = t2("voronoi two.t2");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.out, "line 0 1\n");
  EXPECT_TRUE(has(r.err, "two.t2:3: p2 equals p0 (line 1): merged")) << r.err;
}

TEST_F(VoronoiCli, BadAndUndefinedInput) {
  write("bad.t2", "0 0\n1 x\n");
  const Result bad = t2("voronoi bad.t2");
  EXPECT_EQ(bad.status, 2);
  EXPECT_TRUE(has(bad.err, "bad.t2:2")) << bad.err;
  write("omega.t2", "0 0\n1 0\n0 1\n0 1 0\n0 0 1\n");  // no back point, two points on Omega
  const Result u = t2("voronoi omega.t2");
  EXPECT_EQ(u.status, 3);
  EXPECT_TRUE(has(u.err, "undefined")) << u.err;
  EXPECT_TRUE(u.out.empty());
}

TEST_F(VoronoiCli, FortuneGivesTheFrontHalf) {
  write("sq.t2", "1 0\n0 1\n-1 0\n0 -1\n");
  const Result r = t2("voronoi sq.t2 --algorithm fortune");
  ASSERT_EQ(r.status, 0) << r.err;
  const Parsed p = parse(r.out);
  ASSERT_EQ(p.coords, (std::vector<std::string>{"1 0 0"})) << r.out;  // the front vertex only
  EXPECT_EQ(rotated(p.sites[0]), (std::vector<int>{0, 1, 2, 3}));
  EXPECT_TRUE(p.edges.empty());
  std::vector<std::string> rays = p.rays;  // the four rays leave between two neighbours (s t
  std::sort(rays.begin(), rays.end());     // in the sweep's order)
  EXPECT_EQ(rays, (std::vector<std::string>{"0  0 -1 -1  3 2", "0  0 -1 1  2 1", "0  0 1 -1  3 0",
                                            "0  0 1 1  0 1"})) << r.out;
  std::vector<Point> pts;
  const Parsed q = generated(" --algorithm fortune", pts);
  const FortuneDiagram fd = fortune(pts);
  ASSERT_EQ(q.coords.size(), fd.size());
  EXPECT_EQ(q.edges.size(), fd.edges.size());
  EXPECT_EQ(q.rays.size(), fd.rays.size());
  for (FortuneDiagram::Index v = 0; v < fd.size(); ++v) EXPECT_EQ(exact_of(q.coords[v]), fd.vertex(v));
  write("back.t2", "0 0\n1 0\n-1 2 3\n");  // a back point: Fortune's sweep refuses it
  const Result b = t2("voronoi back.t2 --algorithm fortune");
  EXPECT_EQ(b.status, 3);
  EXPECT_TRUE(has(b.err, "not on the front side")) << b.err;
}

TEST_F(VoronoiCli, DrawsTheDiagram) {
  write("tri.t2", "0 0\n4 0\n0 3\n1 1\n");
  const Result r = t2("voronoi tri.t2 --svg v.svg --model both --scene v.scene");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_TRUE(has(slurp(dir_ / "v.svg"), "<svg"));
  EXPECT_TRUE(has(slurp(dir_ / "v.scene"), "segment"));
}

}  // namespace
}  // namespace t2::testing
