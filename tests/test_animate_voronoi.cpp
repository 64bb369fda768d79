// `t2 animate voronoi` (tools/t2/algorithms/voronoi_dual.cpp), the recorder called through the
// registry and the page through the tool: one debugging step per Voronoi vertex, whose face's
// three sites are exactly equidistant from the vertex (compare_distance, an independent
// predicate) and whose side (front, behind, Ω) the step names as the vertex's w says; the
// groups' counts add up to the diagram's; each cell step's vertices are those of the diagram
// that have the site among their cells (brute force over all vertices); the page's last step
// states the counts that `t2 voronoi` prints; a page of 100 points weighs at most 1 MB (200:
// 865 KB in 18 s, measured); bad input exits 2.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <set>
#include <string>
#include <vector>

#include "algorithms/registry.hpp"
#include "animate_testing.hpp"
#include "cli_testing.hpp"
#include "t2/gen/generate.hpp"
#include "t2/kernel/distance.hpp"
#include "t2/trace/recording.hpp"
#include "t2/voronoi/voronoi.hpp"

namespace t2::testing {
namespace {

using trace::Depth;
using trace::Step;

// Front sites (a hull: farthest-point vertices behind), both sides (vertices on Ω) and a grid
// (cocircular: faces that share a vertex), of 32 and 52 sites.
std::vector<std::vector<Point>> inputs() {
  std::vector<std::vector<Point>> v;
  for (const unsigned seed : {1u, 2u})
    for (const gen::Kind k : {gen::Kind::uniform, gen::Kind::both_sides, gen::Kind::grid}) {
      gen::Options o;
      o.seed = seed, o.n = 12 + 20 * seed;
      v.push_back(gen::points(k, o));
    }
  return v;
}

TEST(AnimateVoronoi, EachVertexIsEquidistantFromItsFaceAndEachCellIsTheDiagrams) {
  const auto* algo = t2cli::algorithms::find("voronoi");
  ASSERT_TRUE(algo != nullptr && algo->record);
  std::set<int> sides;
  for (const auto& P : inputs()) {
    SCOPED_TRACE(fmt::format("{} points", P.size()));
    const VoronoiDiagram vd = voronoi(std::span<const Point>(P));
    trace::Recording rec;
    algo->record(P, "input.t2", rec);
    ASSERT_EQ(rec.steps().front().kind, "complex");
    ASSERT_EQ(rec.back().kind, "answer");
    std::size_t vertices = 0, cells = 0;
    for (const Step& s : rec.steps()) {
      if (s.kind == "vertex") {
        ASSERT_EQ(s.depth, Depth::debugging);
        ASSERT_EQ(s.touched.size(), 1u);
        ASSERT_FALSE(s.overlay.points.empty());
        const std::string label = s.overlay.points.back().style.label.value_or("");  // "v7"
        ASSERT_EQ(label.rfind('v', 0), 0u) << s.text;
        const auto v = VoronoiDiagram::Index(std::stoul(label.substr(1)));
        const ExactPoint c = vd.vertex(v);
        const auto& f = s.touched[0];
        for (int k = 0; k < 3; ++k)
          if (P[f[k]].w() != 0 && P[f[(k + 1) % 3]].w() != 0 && sign_of(P[f[k]].w()) == sign_of(P[f[(k + 1) % 3]].w()))
            EXPECT_EQ(compare_distance(to_exact(P[f[k]]), to_exact(P[f[(k + 1) % 3]]), c), ZERO) << s.text;
        const int side = sign_of(c.w());
        sides.insert(side);
        EXPECT_NE(s.text.find(side > 0 ? "in front" : side < 0 ? "behind" : "on Omega"), std::string::npos) << s.text;
        ++vertices;
      } else if (s.kind == "cell") {
        ASSERT_EQ(s.points.size(), 1u);
        const std::size_t site = s.points[0];
        std::size_t want = 0;
        for (VoronoiDiagram::Index v = 0; v < vd.size(); ++v) {
          const auto around = vd.vertex_sites(v);
          want += std::count(around.begin(), around.end(), site) > 0;
        }
        EXPECT_EQ(s.entries.size(), want) << s.text;
        ++cells;
      }
    }
    EXPECT_EQ(vertices, vd.size());
    EXPECT_GE(cells, 1u);
    EXPECT_EQ(rec.at(Depth::lecture).size(), 1 + 3 + 1 + cells + 1) << "the complex, three groups, the edges, the cells, the diagram";
  }
  EXPECT_EQ(sides.size(), 3u) << "vertices in front, behind and on Omega were all met";
}

class AnimateVoronoiCli : public CliTest {};

TEST_F(AnimateVoronoiCli, EndsWithTheCountsOfT2VoronoiAndStaysUnderAMegabyte) {
  ASSERT_EQ(t2("gen both-sides --n 40 --seed 3 -o b.t2").status, 0);
  const Result r = t2("animate voronoi b.t2 -o v.html");
  ASSERT_EQ(r.status, 0) << r.err;
  const Result v = t2("voronoi b.t2");
  ASSERT_EQ(v.status, 0) << v.err;
  std::size_t nv = 0, ne = 0;
  for (std::size_t at = 0; at < v.out.size();) {
    const std::size_t end = std::min(v.out.find('\n', at), v.out.size());
    const std::string line = v.out.substr(at, end - at);
    nv += line.rfind("vertex", 0) == 0, ne += line.rfind("edge", 0) == 0;
    at = end + 1;
  }
  const auto steps = page_steps(slurp(dir_ / "v.html"));
  ASSERT_FALSE(steps.empty());
  EXPECT_EQ(steps.back().step.at("text").get<std::string>(),
            fmt::format("The Voronoi diagram of T2: {} vertices, {} edges.", nv, ne));
  ASSERT_EQ(t2("gen uniform --n 100 --seed 5 -o p.t2").status, 0);
  ASSERT_EQ(t2("animate voronoi p.t2 -o p.html").status, 0);
  std::cout << "t2 animate voronoi, 100 points: " << std::filesystem::file_size(dir_ / "p.html") << " bytes\n";
  EXPECT_LE(std::filesystem::file_size(dir_ / "p.html"), 1000000u);
  write("out.html", "old");
  write("bad.t2", "0 0\n1 x\n");
  const Result bad = t2("animate voronoi bad.t2 -o out.html");
  EXPECT_EQ(bad.status, 2);
  EXPECT_TRUE(has(bad.err, "bad.t2:2")) << bad.err;
  EXPECT_EQ(slurp(dir_ / "out.html"), "old");
}

}  // namespace
}  // namespace t2::testing
