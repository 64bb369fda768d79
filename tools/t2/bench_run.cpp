// One run of the worker of `t2 bench`: see bench_run.hpp.
#include "bench_run.hpp"

#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <sstream>
#include <stdexcept>

#include "process.hpp"
#include "t2/gen/generate.hpp"

namespace t2bench {

const std::vector<std::string>& segment_input_names() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> v;
    for (t2::gen::Kind k : t2::gen::all_kinds())
      if (t2::gen::is_segment_kind(k)) v.emplace_back(t2::gen::name(k));
    return v;
  }();
  return names;
}

const std::vector<std::string>& input_names() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> v = {"uniform", "disk",  "polygon-interior", "normal",     "clustered", "kuzmin",
                                  "circle",  "segment", "boundary",       "grid", "duplicates", "cube", "sphere"};
    v.insert(v.end(), segment_input_names().begin(), segment_input_names().end());
    return v;
  }();
  return names;
}

t2cli::algorithms::Input input_of(const std::string& input) {
  using t2cli::algorithms::Input;
  if (input == "cube" || input == "sphere") return Input::space;
  const auto& s = segment_input_names();
  return std::find(s.begin(), s.end(), input) != s.end() ? Input::segments : Input::plane;
}

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

Measurement measure(const std::filesystem::path& worker, const std::string& problem, const std::string& impl,
                    const std::string& input, std::size_t n, std::uint64_t seed) {
  t2proc::Spec s;
  s.argv = {worker.string(), problem, impl, input, std::to_string(n), std::to_string(seed)};
  s.limits.output_bytes = 1 << 16;
  const t2proc::Result r = t2proc::run(s);
  if (!r.ok()) {
    std::string why = !r.started ? r.error
                      : r.signal ? "killed by signal " + std::to_string(r.signal)
                                 : "exit status " + std::to_string(r.exit_code);
    throw std::runtime_error(impl + " on " + std::to_string(n) + " points of " + input +
                             " failed (" + why + ")" + (r.err.empty() ? "" : ": " + r.err));
  }
  Measurement m = parse_worker_line(r.out);
  m.peak_rss_kb = r.peak_rss_kb;
  return m;
}

}  // namespace t2bench
