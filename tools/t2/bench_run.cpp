// What `t2 bench` can measure and one run of its worker: see bench_run.hpp.
#include "bench_run.hpp"

#include <unistd.h>

#include <cstdlib>
#include <sstream>
#include <stdexcept>

#include "process.hpp"

namespace t2bench {

const std::vector<Impl>& impls() {
  static const std::vector<Impl> all = {
      {"hull", "hull", "t2", "t2::convex_hull (Akl-Toussaint + monotone chain on front input)", true},
      {"graham", "hull", "graham", "t2's Graham scan, O(n log n)", true},
      {"jarvis", "hull", "jarvis", "t2's Jarvis march, O(nh)", true},
      {"monotone", "hull", "monotone", "t2's Andrew monotone chain, O(n log n)", true},
      {"quickhull", "hull", "quickhull", "t2's Quickhull", true},
      {"merge", "hull", "merge", "t2's hemisphere merge (seed 000, Algorithm 4)", true},
      {"layers", "layers", "jarvis", "t2::convex_layers by Jarvis's march on what is left (seed 003), O(n^2)", true},
      {"layers-graham", "layers", "graham", "t2::convex_layers by Graham's scan on what is left, O(n^2 log n)", true},
      {"delaunay", "delaunay", "t2", "t2::delaunay (filtered exact predicates)", true},
      {"owned", "delaunay", "owned", "t2::delaunay(std::move(points)): the result takes the input vector (one copy of the points)", true},
      {"divide", "delaunay", "divide", "t2::delaunay_divide (Guibas-Stolfi divide and conquer, quad-edge)", true},
      {"hull3d", "hull3d", "quickhull", "t2::convex_hull_3d (R^3; quickhull: farthest point first)", true},
      {"incremental", "hull3d", "incremental", "t2's randomized incremental 3-D hull (conflict lists)", true},
      {"gift-wrap", "hull3d", "gift-wrap", "t2's 3-D gift wrapping, O(n) per hull edge", true},
      {"cgal", "hull,delaunay,hull3d", "cgal",
       "CGAL: ch_akl_toussaint (hull), Delaunay_triangulation_2<Epick> (delaunay), convex_hull_3 (hull3d)", true},
      {"qhull", "hull,hull3d", "qhull", "qhull (libqhull_r, default options: merges nearly coplanar facets)", false},
      {"raw", "hull,delaunay", "raw", "ALGO's t2 code (convex_hull, delaunay) on plain double predicates (naive, inexact)", false},
      {"exact", "hull,delaunay", "exact", "ALGO's t2 code with exact GMP arithmetic on every call (no filter)", true},
  };
  return all;
}

const Impl* find_impl(const std::string& name) {
  for (const auto& i : impls())
    if (name == i.name) return &i;
  return nullptr;
}

std::vector<std::string> algorithm_names() {
  return {"hull", "graham", "jarvis", "monotone", "quickhull", "merge", "layers", "delaunay", "hull3d"};
}

std::vector<std::string> default_peers(const std::string& algo) {
  if (algo == "hull") return {"cgal", "qhull"};
  if (algo == "delaunay") return {"divide", "cgal"};
  if (algo == "graham") return {"jarvis"};
  if (algo == "layers") return {"layers-graham"};
  if (algo == "hull3d") return {"cgal", "qhull"};
  return {};
}

const std::vector<std::string>& input_names() {
  static const std::vector<std::string> names = {"uniform",  "disk",     "polygon-interior", "normal",
                                                 "clustered", "kuzmin",  "circle",           "segment",
                                                 "boundary", "grid",     "duplicates", "cube",
                                                 "sphere"};
  return names;
}

bool is_3d_input(const std::string& input) { return input == "cube" || input == "sphere"; }

std::optional<std::filesystem::path> find_worker() {
  namespace fs = std::filesystem;
  if (const char* env = std::getenv("T2_BENCH_WORKER")) {
    if (::access(env, X_OK) == 0) return fs::path(env);
    return std::nullopt;  // asked for this one: no silent fallback
  }
  std::error_code ec;
  const fs::path self = fs::read_symlink("/proc/self/exe", ec);
  std::vector<fs::path> places;
  if (!ec) places.push_back(self.parent_path() / "t2_bench_worker");
#ifdef T2_BINARY_DIR
  places.push_back(fs::path(T2_BINARY_DIR) / "bin" / "t2_bench_worker");
#endif
  for (const auto& p : places)
    if (::access(p.c_str(), X_OK) == 0) return p;
  return std::nullopt;
}

Measurement parse_worker_line(const std::string& line) {
  Measurement m;
  std::istringstream in(line);
  std::string field;
  int seen = 0;
  while (in >> field) {
    const auto eq = field.find('=');
    if (eq == std::string::npos) continue;
    const std::string key = field.substr(0, eq), value = field.substr(eq + 1);
    try {
      if (key == "size") m.size = std::stoull(value), ++seen;
      if (key == "wall") m.wall = std::stod(value), ++seen;
      if (key == "cpu") m.cpu = std::stod(value), ++seen;
      if (key == "input_rss_kb") m.input_rss_kb = std::stol(value), ++seen;
    } catch (const std::exception&) {
      throw std::runtime_error("the worker printed a bad value: " + field);
    }
  }
  if (seen != 4) throw std::runtime_error("the worker printed an unexpected line: " + line);
  return m;
}

Measurement measure(const std::filesystem::path& worker, const std::string& problem, const Impl& impl,
                    const std::string& input, std::size_t n, std::uint64_t seed) {
  t2proc::Spec s;
  s.argv = {worker.string(), problem, impl.worker, input, std::to_string(n), std::to_string(seed)};
  s.limits.output_bytes = 1 << 16;
  const t2proc::Result r = t2proc::run(s);
  if (!r.ok()) {
    std::string why = !r.started ? r.error
                      : r.signal ? "killed by signal " + std::to_string(r.signal)
                                 : "exit status " + std::to_string(r.exit_code);
    throw std::runtime_error(std::string(impl.name) + " on " + std::to_string(n) + " points of " + input +
                             " failed (" + why + ")" + (r.err.empty() ? "" : ": " + r.err));
  }
  Measurement m = parse_worker_line(r.out);
  m.peak_rss_kb = r.peak_rss_kb;
  return m;
}

}  // namespace t2bench
