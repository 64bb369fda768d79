// t2 gen: seeded, reproducible inputs (t2/gen/generate.hpp) written as scene files.
#include <fmt/format.h>

#include <charconv>
#include <optional>
#include <string>

#include "command.hpp"
#include "t2/error.hpp"
#include "t2/gen/generate.hpp"
#include "t2/io.hpp"

namespace t2cli {
namespace {

template <class T>
T number(const std::string& option, const std::string& text) {
  T v{};
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
  if (ec != std::errc() || end != text.data() + text.size())
    throw UsageError(fmt::format("{} needs a number, not '{}'", option, text));
  return v;
}

int run(Args args) {
  std::optional<std::string> kind, output;
  t2::gen::Options o;
  for (std::size_t i = 0; i < args.size(); ++i) {
    const std::string& a = args[i];
    auto value = [&]() -> const std::string& {
      if (i + 1 == args.size()) throw UsageError(fmt::format("{} needs a value", a));
      return args[++i];
    };
    if (a == "--n") {
      o.n = number<std::size_t>(a, value());
    } else if (a == "--seed") {
      o.seed = number<std::uint64_t>(a, value());
    } else if (a == "--back") {
      o.back = number<double>(a, value());
    } else if (a == "--crossings") {
      o.crossings = number<std::size_t>(a, value());
    } else if (a == "--clusters") {
      o.clusters = number<std::size_t>(a, value());
    } else if (a == "--cartesian") {
      o.cartesian = true;
    } else if (a == "-o") {
      output = value();
    } else if (a.size() > 1 && a[0] == '-') {
      throw UsageError(fmt::format("unknown option '{}'", a));
    } else if (kind) {
      throw UsageError("give exactly one KIND");
    } else {
      kind = a;
    }
  }
  if (!kind) throw UsageError("give a KIND (t2 help gen lists them)");
  t2::gen::Kind k;
  try {
    k = t2::gen::kind_from_name(*kind);
  } catch (const t2::BadInput& e) {
    throw UsageError(e.what());
  }
  const std::string text = t2::gen::to_text(k, o);
  if (output)
    t2::write_file_atomically(*output, text);
  else
    fmt::print("{}", text);
  return kOk;
}

const std::string& help() {
  static const std::string h = [] {
    std::string s =
        "Usage: t2 gen KIND [--n N] [--seed S] [--back B] [--crossings C] [--clusters K]\n"
        "                   [--cartesian] [-o FILE]\n"
        "\n"
        "Writes N seeded random points (vertices, segments) of KIND as a scene file: the same\n"
        "options give the same bytes on every machine. Degenerate kinds are exact (collinear\n"
        "points on one line, cocircular points [c, a, b] with a^2 + b^2 = c^2).\n"
        "\n"
        "  --n N          how many (default 1000)\n"
        "  --seed S       the random stream (default 1)\n"
        "  --back B       both-sides: the share behind (default 0.3)\n"
        "  --crossings C  segments: the number of crossings (default 0)\n"
        "  --clusters K   normal: the number of clusters (default 4)\n"
        "  --cartesian    circle: rounded Cartesian points instead of exact homogeneous ones\n"
        "  -o FILE        write FILE (atomically) instead of standard output\n"
        "\nKinds:\n";
    for (auto k : t2::gen::all_kinds())
      s += fmt::format("  {:<17} {}\n", t2::gen::name(k), t2::gen::description(k));
    s += "\nExit status: 0 done; 2 bad usage or impossible options.\n";
    return s;
  }();
  return h;
}

}  // namespace

T2_COMMAND({"gen", "seeded random inputs: points, polygons, segments (scene files)", help().c_str(), run});

}  // namespace t2cli
