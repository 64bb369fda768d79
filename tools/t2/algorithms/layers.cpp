// The convex layers of chapter 06 (t2/hull/layers.hpp), both ways of seed 003.
#include <span>

#include "algorithms/answer.hpp"
#include "algorithms/registry.hpp"
#include "t2/hull/layers.hpp"

namespace t2cli::algorithms {
namespace {

T2_PROBLEM({"layers", "layers", Input::plane});

std::function<t2::Scene(const Points&)> run(t2::LayersMethod m) {
  return [m](const Points& P) { return polygons_scene(P, t2::convex_layers(std::span<const t2::Point>(P), m)); };
}

std::function<Timed(BenchInput&)> timed(t2::LayersMethod m) {
  return [m](BenchInput& in) -> Timed {
    return [&P = in.points, m] { return t2::convex_layers(std::span<const t2::Point>(P), m).size(); };
  };
}

T2_ALGORITHM({.name = "layers",  // what `t2 layers` runs by default
              .problem = "layers",
              .summary = "t2::convex_layers by Jarvis's march on what is left (seed 003), O(n^2)",
              .title = "the convex layers",
              .run = run(t2::LayersMethod::jarvis),
              .time = timed(t2::LayersMethod::jarvis),
              .peers = {"layers-graham"}});

T2_ALGORITHM({.name = "layers-graham",
              .problem = "layers",
              .summary = "t2::convex_layers by Graham's scan on what is left, O(n^2 log n)",
              .title = "the convex layers by Graham's scan",
              .run = run(t2::LayersMethod::graham),
              .time = timed(t2::LayersMethod::graham)});

}  // namespace
}  // namespace t2cli::algorithms
