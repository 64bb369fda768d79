// The Voronoi diagram of T² (chapter 11, t2/voronoi/voronoi.hpp) and its front half by
// Fortune's sweep (t2/voronoi/fortune.hpp): timed by `t2 bench` on points of the plane; not yet
// animated. Fortune's answer is the front half only (its vertices are the dual's front vertices),
// so it is a problem of its own, "voronoi-front": the sizes `t2 bench` compares would differ.
// Boost.Polygon's sweep is its peer `boost` (algorithms/peers.cpp), on the worker's doubles
// rounded to integers; bench/bench_voronoi.cpp times it and CGAL's Delaunay dual on the same
// integer points.
#include "algorithms/registry.hpp"
#include "t2/voronoi/fortune.hpp"
#include "t2/voronoi/voronoi.hpp"

namespace t2cli::algorithms {
namespace {

T2_PROBLEM({"voronoi", "vertices", Input::plane});

T2_ALGORITHM({.name = "voronoi",  // what `t2 voronoi` runs
              .problem = "voronoi",
              .summary = "t2::voronoi: the dual of the Delaunay complex of T2, front and back vertices (Algorithm 11)",
              .title = "the Voronoi diagram of T2 (the dual)",
              .time = [](BenchInput& in) -> Timed {
                return [&P = in.points] { return t2::voronoi(std::span<const t2::Point>(P)).size(); };
              }});

T2_PROBLEM({"voronoi-front", "front vertices", Input::plane});

T2_ALGORITHM({.name = "fortune",  // what `t2 voronoi --algorithm fortune` runs
              .problem = "voronoi-front",
              .summary = "t2::fortune: Fortune's sweep, the front half of the Voronoi diagram, exact (seed 001)",
              .title = "Fortune's sweep",
              .time = [](BenchInput& in) -> Timed {
                return [&P = in.points] { return t2::fortune(std::span<const t2::Point>(P)).size(); };
              },
              .peers = {"boost"}});

}  // namespace
}  // namespace t2cli::algorithms
