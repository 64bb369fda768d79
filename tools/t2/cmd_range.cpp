// t2 range: the points of a scene in closed iso-rectangles of T², counted by the locus method
// (t2/range/locus.hpp), found by a kd-tree (kdtree.hpp) or a range tree (range_tree.hpp), or
// by testing every point (`contains`, bbox.hpp).
#include <fmt/format.h>

#include <charconv>
#include <cmath>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "command.hpp"
#include "scene_argument.hpp"
#include "t2/kernel/bbox.hpp"
#include "t2/kernel/io.hpp"
#include "t2/kernel/scene.hpp"
#include "t2/range/kdtree.hpp"
#include "t2/range/locus.hpp"
#include "t2/range/range_tree.hpp"

namespace t2cli {
namespace cmd_range {

struct Options {
  std::string points, rects;
  std::string algorithm = "brute";
  bool count = false;
};

// The rectangles of RECTS, one a line: "x0 y0 x1 y1" (opposite front corners) or
// "w0 x0 y0 w1 x1 y1" (opposite corners as points of T², iso_rect(a, c)). Blank lines and
// lines starting with '#' are skipped. The corners are converted exactly before the rectangle is
// made, so its far sides are the numbers written, not differences rounded in doubles.
std::vector<t2::ExactIsoRect> read_rects(const std::string& file) {
  const std::string name = file == "-" ? "<stdin>" : file;
  const std::string text = t2::read_file(file == "-" ? "/dev/stdin" : file);
  std::vector<t2::ExactIsoRect> out;
  int line = 0;
  for (std::size_t at = 0; at < text.size();) {
    const std::size_t end = std::min(text.find('\n', at), text.size());
    const std::string l = t2::trim(std::string_view(text).substr(at, end - at));
    at = end + 1;
    ++line;
    if (l.empty() || l[0] == '#') continue;
    std::vector<double> v;
    for (std::size_t k = 0; k < l.size();) {
      const std::size_t e = std::min(l.find_first_of(" \t", k), l.size());
      const std::string_view w = std::string_view(l).substr(k, e - k);
      k = l.find_first_not_of(" \t", e);
      if (k == std::string::npos) k = l.size();
      double x = 0;
      const auto r = std::from_chars(w.data(), w.data() + w.size(), x);
      if (r.ec != std::errc() || r.ptr != w.data() + w.size() || !std::isfinite(x))
        throw t2::ParseError(name, line, fmt::format("'{}' is not a finite number", w));
      v.push_back(x);
    }
    if (v.size() != 4 && v.size() != 6)
      throw t2::ParseError(name, line, fmt::format("a rectangle is 4 numbers (x0 y0 x1 y1) or 6 (w0 x0 y0 w1 x1 y1), "
                                                   "found {}", v.size()));
    const t2::Point a = v.size() == 4 ? t2::Point::cartesian(v[0], v[1]) : t2::Point(v[0], v[1], v[2]);
    const t2::Point c = v.size() == 4 ? t2::Point::cartesian(v[2], v[3]) : t2::Point(v[3], v[4], v[5]);
    try {
      out.push_back(t2::iso_rect(t2::to_exact(a), t2::to_exact(c)));
    } catch (const t2::Undefined& e) {
      throw t2::Undefined(fmt::format("{}:{}: {}", name, line, e.what()));
    }
  }
  return out;
}

int range(const Options& o) {
  if (o.algorithm == "locus" && !o.count)
    throw UsageError("--algorithm locus counts: it needs --count (it cannot list the points)");
  const t2::Scene scene = read_scene_argument(o.points);
  const std::vector<t2::Point> P = scene_points(scene);
  const std::vector<t2::ExactIsoRect> R = read_rects(o.rects);
  std::string out;
  auto answer = [&](const auto& S) {
    for (const auto& r : R)
      out += o.count ? fmt::format("{}\n", S.count(r)) : fmt::format("{}\n", fmt::join(S.report(r), " "));
  };
  if (o.algorithm == "locus") {
    const t2::LocusCounter L(P);
    for (const auto& r : R) out += fmt::format("{}\n", L.count(r));
  } else if (o.algorithm == "kdtree") {
    answer(t2::KdTree(P));
  } else if (o.algorithm == "rangetree") {
    answer(t2::RangeTree(P));
  } else {
    std::vector<t2::ExactPoint> E;
    for (const auto& p : P) E.push_back(t2::to_exact(p));
    for (const auto& r : R) {
      const t2::ExactBBox b = t2::bbox(r);
      std::vector<std::size_t> in;
      for (std::size_t i = 0; i < E.size(); ++i)
        if (t2::contains(b, E[i])) in.push_back(i);
      out += o.count ? fmt::format("{}\n", in.size()) : fmt::format("{}\n", fmt::join(in, " "));
    }
  }
  fmt::print("{}", out);
  return kOk;
}

Action setup(Arguments& app) {
  auto o = std::make_shared<Options>();
  app.description(
      "Prints, for each closed iso-rectangle of RECTS, the ascending indices of the points of\n"
      "the scene file POINTS inside it (numbered from 0 in file order), or with --count their\n"
      "number. RECTS holds one rectangle a line: 'x0 y0 x1 y1' (opposite corners on the front\n"
      "side) or 'w0 x0 y0 w1 x1 y1' (opposite corners as points of T2: the first proper, the\n"
      "second on its side, or on Omega off the axes for a quadrant that reaches Omega). A\n"
      "rectangle holds the points of its side inside it or on its boundary, and the points\n"
      "of Omega it reaches.");
  app.add_option("POINTS", o->points, "the scene file of points, - for standard input")->required();
  app.add_option("RECTS", o->rects, "the rectangles, one a line")->required();
  app.add_option("--algorithm", o->algorithm,
                 "brute (default: every point tested), locus (seed 000's Algorithms 17-18:\n"
                 "O(n^2) preprocessing, O(log n) a query; counts only), kdtree (O(n log n)\n"
                 "preprocessing, O(sqrt n + k) a query) or rangetree (fractional cascading:\n"
                 "O(n log n) time and memory, O(log n + k) a query)")
      ->type_name("A")
      ->check(IsMember({"brute", "locus", "kdtree", "rangetree"}));
  app.add_flag("--count", o->count, "print the number of points, not their indices");
  app.footer(
      "Exit status: 0 done; 2 bad usage or bad input (file:line: what is wrong); 3 a\n"
      "rectangle undefined in T2 (corners on different sides, or a corner at infinity on an\n"
      "axis direction).");
  return [o] { return range(*o); };
}

}  // namespace cmd_range

T2_COMMAND({"range", "the points of a scene in iso-rectangles of T2 (counted or listed)", cmd_range::setup});

}  // namespace t2cli
