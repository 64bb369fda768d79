#pragma once
// How one measurement of `t2 bench` runs (cmd_bench.cpp): the inputs, and one run of the
// benchmark worker (bench/t2_bench_worker.cpp, which links CGAL and qhull; the t2 tool never
// does) in a fresh child process. What can be measured, the algorithms and their peers, is the
// registry's (tools/t2/algorithms/registry.hpp).

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "algorithms/registry.hpp"

namespace t2bench {

/// The inputs (t2 gen kinds with front points, and clustered; cube and sphere for hull3d; the
/// kinds of segments for intersect).
const std::vector<std::string>& input_names();
/// The t2 gen kinds of segments (t2::gen::is_segment_kind), the inputs of intersect.
const std::vector<std::string>& segment_input_names();
/// What an input is: points of R³ (cube, sphere), segments (segment_input_names) or points of
/// the plane.
t2cli::algorithms::Input input_of(const std::string& input);

/// One measurement.
struct Measurement {
  std::size_t size = 0;     ///< the answer's size (hull vertices, layers, finite triangles)
  double wall = 0;          ///< seconds of the run alone
  double cpu = 0;           ///< CPU seconds of the run alone
  long peak_rss_kb = 0;     ///< the worker's peak resident memory (input included)
  long input_rss_kb = 0;    ///< its peak before the run (the input and the peer's copy)
};

/// The worker: $T2_BENCH_WORKER, else t2_bench_worker beside the running t2, else in the build
/// tree t2 was built in; nullopt when none exists (the caller says how to build it).
std::optional<std::filesystem::path> find_worker();

/// Runs the worker once: the implementation named `impl` (a registered algorithm or peer)
/// solving `problem` ("hull", "delaunay") on n points of `input` made with `seed`. Throws
/// std::runtime_error with the worker's message when it fails.
Measurement measure(const std::filesystem::path& worker, const std::string& problem, const std::string& impl,
                    const std::string& input, std::size_t n, std::uint64_t seed);

/// Parses the worker's line "size=S wall=W cpu=C input_rss_kb=R"; throws std::runtime_error.
Measurement parse_worker_line(const std::string& line);

}  // namespace t2bench
