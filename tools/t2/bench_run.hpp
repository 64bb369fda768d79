#pragma once
// What `t2 bench` can measure and how one measurement runs (cmd_bench.cpp): the algorithms and
// their peers, the inputs, and one run of the benchmark worker (bench/t2_bench_worker.cpp, which
// links CGAL and qhull; the t2 tool never does) in a fresh child process.

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace t2bench {

/// An implementation that `t2 bench` can time.
struct Impl {
  const char* name;     ///< its name on the command line and in the table
  const char* problem;  ///< what it computes: "hull", "layers", "delaunay", "hull3d", or a list ("hull,delaunay")
  const char* worker;   ///< its name for the worker
  const char* what;     ///< one line for the help
  bool exact;           ///< exact predicates: its answer must equal the algorithm's
};

/// Every implementation, algorithms of t2 first.
const std::vector<Impl>& impls();
/// The implementation of a name, or nullptr.
const Impl* find_impl(const std::string& name);
/// The names ALGO accepts (the t2 algorithms).
std::vector<std::string> algorithm_names();
/// The peers measured when `--vs` is not given (hull and hull3d: cgal, qhull; delaunay: divide,
/// cgal; graham: jarvis; layers: layers-graham).
std::vector<std::string> default_peers(const std::string& algo);
/// The inputs (t2 gen kinds with front points, and clustered; cube and sphere for hull3d).
const std::vector<std::string>& input_names();
/// True for the inputs of R³ (cube, sphere), the only ones of hull3d.
bool is_3d_input(const std::string& input);

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

/// Runs the worker once: `impl` solving `problem` ("hull", "delaunay") on n points of `input`
/// made with `seed`. Throws std::runtime_error with the worker's message when it fails.
Measurement measure(const std::filesystem::path& worker, const std::string& problem, const Impl& impl,
                    const std::string& input, std::size_t n, std::uint64_t seed);

/// Parses the worker's line "size=S wall=W cpu=C input_rss_kb=R"; throws std::runtime_error.
Measurement parse_worker_line(const std::string& line);

}  // namespace t2bench
