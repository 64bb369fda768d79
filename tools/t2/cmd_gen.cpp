// t2 gen: seeded, reproducible inputs (t2/gen/generate.hpp) written as scene files.
#include <fmt/format.h>

#include <memory>
#include <string>

#include "command.hpp"
#include "t2/kernel/error.hpp"
#include "t2/gen/generate.hpp"
#include "t2/kernel/io.hpp"

namespace t2cli {
namespace cmd_gen {

struct Options {
  std::string kind;
  std::string output;
  t2::gen::Options gen;
};

int generate(const Options& o) {
  t2::gen::Kind k;
  try {
    k = t2::gen::kind_from_name(o.kind);
  } catch (const t2::BadInput& e) {
    throw UsageError(e.what());
  }
  const std::string text = t2::gen::to_text(k, o.gen);
  if (!o.output.empty())
    t2::write_file_atomically(o.output, text);
  else
    fmt::print("{}", text);
  return kOk;
}

std::string kinds() {
  std::string s = "Kinds:\n";
  for (auto k : t2::gen::all_kinds()) s += fmt::format("  {:<17} {}\n", t2::gen::name(k), t2::gen::description(k));
  return s;
}

Action setup(Arguments& app) {
  auto o = std::make_shared<Options>();
  app.description(
      "Writes N seeded random points (vertices, segments) of KIND as a scene file: the same\n"
      "options give the same bytes on every machine. Degenerate kinds are exact (collinear\n"
      "points on one line, cocircular points [c, a, b] with a^2 + b^2 = c^2).");
  app.add_option("KIND", o->kind, "what to make (the kinds are listed below)")->required();
  app.add_option("--n", o->gen.n, "how many (default 1000)")->type_name("N");
  app.add_option("--seed", o->gen.seed, "the random stream (default 1)")->type_name("S");
  app.add_option("--back", o->gen.back, "both-sides: the share behind (default 0.3)")
      ->type_name("B")
      ->check(Range(0.0, 1.0));
  app.add_option("--crossings", o->gen.crossings, "segments: the number of crossings (default 0)")->type_name("C");
  app.add_option("--clusters", o->gen.clusters, "normal: the number of clusters (default 4)")
      ->type_name("K")
      ->check(PositiveNumber);
  app.add_flag("--cartesian", o->gen.cartesian, "circle: rounded Cartesian points instead of exact homogeneous ones");
  app.add_flag("--untangle", o->gen.untangle,
               "simple-polygon: 2-opt untangling of the points in random order instead of space partitioning");
  app.add_option("-o", o->output, "write FILE (atomically) instead of standard output")->type_name("FILE");
  app.footer(kinds() + "\nExit status: 0 done; 2 bad usage or impossible options.");
  return [o] { return generate(*o); };
}

}  // namespace cmd_gen

T2_COMMAND({"gen", "seeded random inputs: points, polygons, segments (scene files)", cmd_gen::setup});

}  // namespace t2cli
