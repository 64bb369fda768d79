// t2 bench: one harness for every benchmark of the course. An algorithm of t2, alone or against
// peers (CGAL, qhull, another t2 algorithm, the same code on other predicates), over a range of
// n on a chosen generator: wall and CPU time and peak memory per run, a table on stdout, the
// fitted growth exponent, and a log-log plot (<t2/draw/loglog.hpp>). Every measurement runs in a fresh
// process of the benchmark worker (bench/t2_bench_worker.cpp: it links CGAL and qhull, this tool
// never does), so peak memories never add up and one crash loses one run.
#include <fmt/format.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <map>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "algorithms/registry.hpp"
#include "bench_progress.hpp"
#include "bench_run.hpp"
#include "bench_stats.hpp"
#include "command.hpp"
#include "t2/kernel/io.hpp"
#include <t2/draw/loglog.hpp>

namespace t2cli {
namespace cmd_bench {

using namespace t2bench;

struct Options {
  std::string algo;
  std::size_t n = 0;
  std::string range;
  std::string input;  // default: uniform, cube for hull3d
  std::vector<std::string> vs;
  std::string plot, csv;
  int repeat = 1;
  int per_decade = 2;
  std::uint64_t seed = 1;
};

// An implementation to time: a registered t2 algorithm or peer (algorithms/registry.hpp).
struct Impl {
  std::string name;
  bool exact = true;  ///< exact predicates: its answer must equal the algorithm's
};

// The medians of the repeats of one implementation at one size.
struct Row {
  const Impl* impl;
  std::size_t n = 0, size = 0;
  double wall = 0, cpu = 0, peak_kb = 0, input_kb = 0;
};

std::vector<std::string> timed_names() {
  std::vector<std::string> names;
  for (const auto* a : algorithms::timed()) names.push_back(a->name);
  return names;
}

// The implementations to run, the algorithm first; throws UsageError.
std::vector<Impl> chosen(const Options& o, const algorithms::Algorithm*& algo) {
  algo = algorithms::find(o.algo);
  if (algo == nullptr || !algo->time)
    throw UsageError(fmt::format("unknown algorithm '{}' (one of: {})", o.algo, fmt::join(timed_names(), ", ")));
  std::vector<Impl> out{{algo->name, true}};
  std::vector<std::string> peers = o.vs.empty() ? algo->peers : o.vs;
  if (peers.size() == 1 && peers[0] == "none") peers.clear();
  for (const auto& p : peers) {
    const algorithms::Algorithm* a = algorithms::find(p);
    const algorithms::Peer* f = algorithms::find_peer(p);
    const bool serves = (a != nullptr && a->time && a->problem == algo->problem) ||
                        (f != nullptr && std::find(f->problems.begin(), f->problems.end(), algo->problem) !=
                                             f->problems.end());
    if (!serves || p == algo->name)
      throw UsageError(fmt::format("--vs {}: not a peer of {} (peers: see t2 help bench)", p, o.algo));
    if (f != nullptr && f->same_code && algo->name != algo->problem)
      throw UsageError(fmt::format("--vs {}: swaps the predicates of t2 bench {} only (the problem's own algorithm)",
                                   p, algo->problem));
    if (std::none_of(out.begin(), out.end(), [&](const Impl& i) { return i.name == p; }))
      out.push_back({p, f == nullptr || f->exact});
  }
  return out;
}

std::vector<std::size_t> sizes(const Options& o) {
  if (o.n != 0 && !o.range.empty()) throw UsageError("give --n or --range, not both");
  if (o.range.empty()) return {o.n != 0 ? o.n : 100000};
  try {
    const auto [a, b] = parse_range(o.range);
    return log_steps(a, b, o.per_decade);
  } catch (const std::invalid_argument& e) {
    throw UsageError(e.what());
  }
}

double load_average() {
  double l[1] = {0};
  return ::getloadavg(l, 1) == 1 ? l[0] : 0;
}

// The runs, with the progress line on stderr (erased before this returns, so before the table).
std::vector<Row> run_all(const Options& o, const std::string& problem, const std::vector<Impl>& impls,
                         const std::vector<std::size_t>& ns, const std::filesystem::path& worker,
                         Progress::Setting shown) {
  std::vector<const Impl*> run;
  for (const Impl& i : impls) run.push_back(&i);
  Progress progress(ns.size() * run.size() * std::size_t(o.repeat), shown.tick, shown.shown);
  std::size_t k = 0;
  std::vector<Row> rows;
  for (std::size_t n : ns) {
    std::map<const Impl*, std::vector<Measurement>> got;
    for (int r = 0; r < o.repeat; ++r)  // repeats interleaved: a burst of load hits every peer
      for (const Impl* i : run) {
        progress.start(++k, i->name, n);
        got[i].push_back(measure(worker, problem, i->name, o.input, n, o.seed));
      }
    for (const Impl* i : run) {
      const auto& ms = got[i];
      auto med = [&](auto field) {
        std::vector<double> v;
        for (const auto& m : ms) v.push_back(double(field(m)));
        return median(v);
      };
      Row row{i, n, ms[0].size};
      row.wall = med([](const Measurement& m) { return m.wall; });
      row.cpu = med([](const Measurement& m) { return m.cpu; });
      row.peak_kb = med([](const Measurement& m) { return m.peak_rss_kb; });
      row.input_kb = med([](const Measurement& m) { return m.input_rss_kb; });
      for (const auto& m : ms)
        if (m.size != row.size) throw std::runtime_error(fmt::format("{} gave different answers on the same input", i->name));
      rows.push_back(row);
    }
  }
  return rows;
}

int bench(Options o) {
  const algorithms::Algorithm* algo = nullptr;
  const std::vector<Impl> impls = chosen(o, algo);
  std::vector<const Impl*> run;
  for (const Impl& i : impls) run.push_back(&i);
  const std::string problem = algo->problem;
  const algorithms::Problem* pr = algorithms::find_problem(problem);
  if (pr == nullptr) throw std::logic_error("t2 bench " + o.algo + ": its problem " + problem + " is not registered");
  using algorithms::Input;
  if (o.input.empty()) o.input = pr->input == Input::space ? "cube" : pr->input == Input::segments ? "segments" : "uniform";
  const auto& inputs = input_names();
  if (std::find(inputs.begin(), inputs.end(), o.input) == inputs.end())
    throw UsageError(fmt::format("--input {}: one of {}", o.input, fmt::join(inputs, ", ")));
  if (input_of(o.input) != pr->input)
    throw UsageError(fmt::format("--input {}: {} takes {}", o.input, o.algo,
                                 pr->input == Input::space ? std::string("points of R^3 (cube, sphere)")
                                 : pr->input == Input::segments
                                     ? fmt::format("segments ({})", fmt::join(segment_input_names(), ", "))
                                     : std::string("points of the plane (not cube, sphere, nor a kind of segments)")));
  const std::vector<std::size_t> ns = sizes(o);
  if (ns.front() < 1) throw UsageError("--n must be at least 1");
  Progress::Setting shown{};
  try {
    shown = Progress::setting(::isatty(2) != 0, std::getenv("T2_BENCH_PROGRESS"));
  } catch (const std::invalid_argument& e) {
    throw UsageError(e.what());
  }
  const auto worker = find_worker();
  if (!worker) {
    fmt::print(stderr,
               "t2 bench: the benchmark worker t2_bench_worker is not built{} (it links CGAL and qhull, which the t2 "
               "tool never does). Build it:\n  cmake --build --preset default --target t2_bench_worker\n(qhull "
               "comes from Debian's libqhull-dev, see scripts/deps.sh)\n",
               std::getenv("T2_BENCH_WORKER") ? fmt::format(" (T2_BENCH_WORKER={})", std::getenv("T2_BENCH_WORKER")) : "");
    return kFailed;
  }
  std::vector<Row> rows;
  try {
    rows = run_all(o, problem, impls, ns, *worker, shown);
  } catch (const std::runtime_error& e) {
    fmt::print(stderr, "t2 bench: {}\n", e.what());
    return kFailed;
  }
  // The table: medians of the repeats; ratio = the algorithm's CPU time / this row's.
  fmt::print("# t2 bench {} --input {} --seed {}: medians of {} run(s) each, every run in its own process; "
             "load average {:.1f} on {} cores when it started\n",
             o.algo, o.input, o.seed, o.repeat, load_average(), ::sysconf(_SC_NPROCESSORS_ONLN));
  fmt::print("# size: hull vertices, layers, finite triangles or intersection points; peak: the worker's peak RSS (input included); run B/pt: "
             "peak above the input, per point; ratio: {} CPU time / this row's\n",
             o.algo);
  std::size_t name_width = 10;  // the first column fits the longest name ("layers-graham")
  for (const Impl* i : run) name_width = std::max(name_width, std::string_view(i->name).size());
  fmt::print("{:<{}} {:>10} {:>10} {:>10} {:>10} {:>9} {:>8} {:>7}  {}\n", "impl", name_width, "n", "size", "wall_s",
             "cpu_s", "peak_MiB", "run_B/pt", "ratio", "agrees");
  std::vector<std::string> disagreements, notes;
  std::string csv = "impl,n,size,wall_s,cpu_s,peak_rss_kb,input_rss_kb\n";
  for (const Row& r : rows) {
    const Row& ref = *std::find_if(rows.begin(), rows.end(), [&](const Row& x) { return x.n == r.n && x.impl == run[0]; });
    std::string agrees = r.impl == run[0] ? "-" : r.size == ref.size ? "yes" : r.impl->exact ? "NO" : "differs (inexact)";
    if (r.size != ref.size) {
      const std::string what = fmt::format("n = {}: {} has {} {}, {} has {}", r.n, o.algo, ref.size, pr->size_word,
                                           r.impl->name, r.size);
      (r.impl->exact ? disagreements : notes).push_back(what);
    }
    fmt::print("{:<{}} {:>10} {:>10} {:>10.4g} {:>10.4g} {:>9.1f} {:>8.1f} {:>7.3f}  {}\n", r.impl->name, name_width, r.n, r.size,
               r.wall, r.cpu, r.peak_kb / 1024, (r.peak_kb - r.input_kb) * 1024 / double(r.n),
               r.cpu > 0 ? ref.cpu / r.cpu : 0.0, agrees);
    csv += fmt::format("{},{},{},{:.9g},{:.9g},{:.0f},{:.0f}\n", r.impl->name, r.n, r.size, r.wall, r.cpu, r.peak_kb,
                       r.input_kb);
  }
  std::vector<t2::draw::Series> series;
  std::vector<std::string> growth;
  for (const Impl* i : run) {
    t2::draw::Series s{i->name, {}, {}};
    for (const Row& r : rows)
      if (r.impl == i) s.n.push_back(double(r.n)), s.t.push_back(r.cpu);
    if (t2::draw::fit_defined(s.n, s.t)) growth.push_back(fmt::format("{} n^{:.2f}", i->name, t2::draw::fit_power_law(s.n, s.t).exponent));
    series.push_back(std::move(s));
  }
  if (!growth.empty())
    fmt::print("growth (least squares on log cpu time against log n): {}\n", fmt::join(growth, ", "));
  for (const auto& n : notes) fmt::print("note: {} (an inexact peer)\n", n);
  if (!o.plot.empty())
    t2::write_file_atomically(o.plot, t2::draw::loglog_svg(series, fmt::format("t2 bench {}: CPU time, input {}", o.algo, o.input),
                                               "CPU seconds (log scale)"));
  if (!o.csv.empty()) t2::write_file_atomically(o.csv, csv);
  for (const auto& d : disagreements) fmt::print(stderr, "t2 bench: ANSWERS DIFFER: {}\n", d);
  return disagreements.empty() ? kOk : kFailed;
}

// The registry's algorithms and peers, by problem, and the default peers.
std::string catalogue() {
  std::string s = "Algorithms (ALGO; each is also a peer of the others of its problem) and peers (--vs):\n";
  std::vector<std::string> defaults;
  for (const auto& pr : algorithms::problems()) {
    s += fmt::format(" {} ({} input; size: {}):\n", pr.name, pr.input == algorithms::Input::space ? "R^3" : pr.input == algorithms::Input::segments ? "segments" : "T2", pr.size_word);
    for (const auto* a : algorithms::timed())
      if (a->problem == pr.name) {
        s += fmt::format("  {:<15} {}\n", a->name, a->summary);
        if (!a->peers.empty()) defaults.push_back(fmt::format("{} --vs {}", a->name, fmt::join(a->peers, ",")));
      }
    for (const auto& f : algorithms::peers())
      if (std::find(f.problems.begin(), f.problems.end(), pr.name) != f.problems.end())
        s += fmt::format("  {:<15} {}{}\n", f.name, f.summary, f.same_code ? fmt::format(" (t2 bench {} only)", pr.name) : "");
  }
  s += fmt::format("Inputs (--input, from t2 gen; normal = one cluster, clustered = 64): {}\n",
                   fmt::join(input_names(), ", "));
  s += fmt::format("Default peers: {}; --vs none for ALGO alone.\n", fmt::join(defaults, "; "));
  return s;
}

Action setup(Arguments& app) {
  auto o = std::make_shared<Options>();
  app.description(
      "Times ALGO (and its peers) on seeded inputs, every run in a fresh process of the benchmark\n"
      "worker: wall and CPU time and peak memory, the medians of the repeats in a table, the\n"
      "growth exponent fitted over a range of n, and a log-log plot. The worker checks nothing by\n"
      "itself; this command compares the answers' sizes and fails when an exact peer disagrees.\n"
      "Examples: t2 bench hull --n 10000000; t2 bench delaunay --input grid --repeat 3;\n"
      "t2 bench graham --vs jarvis --input circle --range 1000..100000 --plot gj.svg;\n"
      "t2 bench delaunay --vs raw,exact --range 1000..100000 (the cost of exactness; hull too).");
  app.add_option("ALGO", o->algo, "the t2 algorithm: " + algorithms::words(timed_names()))->required();
  app.add_option("--n", o->n, "the number of points (default 100000)")->type_name("N")->check(PositiveNumber);
  app.add_option("--range", o->range, "sizes from N1 to N2 in logarithmic steps")->type_name("N1..N2");
  app.add_option("--per-decade", o->per_decade, "steps of --range per factor 10 (default 2)")
      ->type_name("K")
      ->check(Range(1, 20));
  app.add_option("--input", o->input, "the generator (default uniform; cube for hull3d)")->type_name("KIND");
  app.add_option("--vs", o->vs, "peers, comma-separated (default: see below)")->type_name("PEER")->delimiter(',');
  app.add_option("--repeat", o->repeat, "runs per measurement; the table gives medians (default 1)")
      ->type_name("R")
      ->check(Range(1, 1000));
  app.add_option("--seed", o->seed, "the generator's seed (default 1)")->type_name("S");
  app.add_option("--plot", o->plot, "write the log-log plot of CPU time (SVG, atomically)")->type_name("OUT.svg");
  app.add_option("--csv", o->csv, "write the medians as CSV (atomically)")->type_name("OUT.csv");
  app.footer(catalogue() +
             "\nA progress line on stderr, rewritten in place every second and erased before the table, when\n"
             "stderr is a terminal and the benchmark lasts over a second; T2_BENCH_PROGRESS=SECONDS shows\n"
             "it on any stderr, every SECONDS.\n"
             "\nExit status: 0 done; 1 a run failed, the worker is not built, or an exact peer's answer differs;\n"
             "2 bad usage.");
  return [o] { return bench(*o); };
}

}  // namespace cmd_bench

T2_COMMAND({"bench", "time algorithms against peers over n: table, growth exponent, log-log plot", cmd_bench::setup});

}  // namespace t2cli
