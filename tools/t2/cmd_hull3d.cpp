// t2 hull3d: the convex hull of points of R³ (t2/hull3d.hpp), as outward triangles, optionally drawn.
#include <fmt/format.h>

#include <charconv>
#include <cmath>
#include <iostream>
#include <iterator>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "command.hpp"
#include "t2/draw/polyhedron.hpp"
#include "t2/hull3d.hpp"
#include "t2/kernel/io.hpp"
#include "t2/kernel/scene.hpp"

namespace t2cli {
namespace cmd_hull3d {

struct Options {
  std::string file;
  std::string algorithm = "quickhull";
  std::string svg;
  bool facets = false;
  double azimuth = 35, elevation = 25;
};

// Lines `x y z`; blank lines and everything after '#' are ignored.
std::vector<t2::Point3> read_points3(const std::string& file) {
  const std::string name = file == "-" ? "<stdin>" : file;
  const std::string text = file == "-" ? std::string((std::istreambuf_iterator<char>(std::cin)), std::istreambuf_iterator<char>())
                                       : t2::read_file(file);
  std::vector<t2::Point3> P;
  std::istringstream in(text);
  std::string line;
  for (int number = 1; std::getline(in, line); ++number) {
    if (const auto hash = line.find('#'); hash != std::string::npos) line.erase(hash);
    std::istringstream words(line);
    std::vector<std::string> w{std::istream_iterator<std::string>(words), std::istream_iterator<std::string>()};
    if (w.empty()) continue;
    if (w.size() != 3)
      throw t2::ParseError(name, number, fmt::format("expected three coordinates 'x y z', found {} words", w.size()));
    double c[3];
    for (int k = 0; k < 3; ++k) {
      const auto [end, ec] = std::from_chars(w[k].data(), w[k].data() + w[k].size(), c[k]);
      if (ec != std::errc() || end != w[k].data() + w[k].size() || !std::isfinite(c[k]))
        throw t2::ParseError(name, number, fmt::format("'{}' is not a finite number", w[k]));
    }
    P.push_back({c[0], c[1], c[2]});
  }
  return P;
}

int hull3d(const Options& o) {
  t2::Hull3dAlgorithm a = t2::Hull3dAlgorithm::quickhull;
  for (auto b : t2::hull3d_algorithms)
    if (o.algorithm == t2::name(b)) a = b;
  const std::vector<t2::Point3> P = read_points3(o.file);
  const t2::Facets F = t2::hull_facets_3d(P, a);
  if (!o.svg.empty()) {
    t2::draw::View3 v;
    v.azimuth = o.azimuth;
    v.elevation = o.elevation;
    t2::draw::save_polyhedron(t2::polyhedron_of(P, F), v, o.svg, P);
  }
  std::string out;
  if (o.facets) {
    for (const auto& f : F) {
      for (std::size_t k = 0; k < f.size(); ++k) out += (k ? " " : "") + std::to_string(f[k]);
      out += '\n';
    }
  } else {
    for (const auto& t : t2::fan_triangles(F)) out += fmt::format("{} {} {}\n", t[0], t[1], t[2]);
  }
  fmt::print("{}", out);
  return kOk;
}

Action setup(Arguments& app) {
  auto o = std::make_shared<Options>();
  app.description(
      "Prints the convex hull of the points of R3 in FILE (- for standard input; lines 'x y z',\n"
      "'#' starts a comment) as triangles, one per line: three 0-based indices of input points\n"
      "(in file order), counter-clockwise seen from outside (the outward normal is\n"
      "(b - a) x (c - a)). Only strict vertices appear (points inside facets or edges do not);\n"
      "of equal points, the first. A facet with more than three vertices (coplanar points) is\n"
      "given as the fan from its smallest index. Lines are sorted, each starting at its\n"
      "smallest index, so every algorithm prints the same bytes.");
  app.add_option("FILE", o->file, "the points, - for standard input")->required();
  app.add_option("--algorithm", o->algorithm, "quickhull (default), incremental (random order) or gift-wrap")
      ->type_name("A")
      ->check(IsMember(names_of(t2::hull3d_algorithms)));
  app.add_flag("--facets", o->facets, "print the facets instead: one polygon per line, counter-clockwise from outside");
  app.add_option("--svg", o->svg, "also draw the hull and the points to OUT (.svg, .png or .pdf, atomically)")
      ->type_name("OUT");
  app.add_option("--azimuth", o->azimuth, "the viewer's azimuth for --svg, degrees (default 35)");
  app.add_option("--elevation", o->elevation, "the viewer's elevation for --svg, degrees (default 25)");
  app.footer(
      "Exit status: 0 done; 2 bad usage or bad input (file:line: what is wrong); 3 the hull is no\n"
      "polyhedron: fewer than four points off one plane (no point, all equal, all collinear, or\n"
      "all coplanar), said on standard error.");
  return [o] { return hull3d(*o); };
}

}  // namespace cmd_hull3d

T2_COMMAND({"hull3d", "the convex hull of points of R3 (outward triangles)", cmd_hull3d::setup});

}  // namespace t2cli
