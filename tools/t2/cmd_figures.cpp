// t2 figures: regenerate every figure of the book (chapter programs and the gallery), or check
// that the committed figures are what the programs draw.
#include <fmt/format.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <map>
#include <memory>
#include <set>
#include <string>
#include <thread>
#include <vector>

#include "command.hpp"
#include "process.hpp"
#include "t2/kernel/error.hpp"
#include "t2/kernel/io.hpp"

namespace t2cli {
namespace cmd_figures {

namespace fs = std::filesystem;

/// One program that writes the figures of one folder figures/<slug>.
struct Job {
  fs::path program;  // bin/chapter_NN or bin/gallery
  std::string slug;  // NN-slug or gallery
  fs::path out;      // the folder given with --figures
  fs::path log;      // its stderr
  int status = -1;   // exit status, -1 when it did not exit normally
};

fs::path bin_dir() {
  std::error_code ec;
  const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
  if (ec) throw t2::BadInput("cannot find the folder of the t2 program (/proc/self/exe)");
  return exe.parent_path();
}

// The programs next to this t2: every chapter_NN whose chapters/NN-slug/ exists in the source
// tree, then gallery.
std::vector<Job> find_jobs(const fs::path& bin, const fs::path& root, std::vector<std::string>& unbuilt) {
  std::map<std::string, std::string> slug_of;  // NN -> NN-slug
  std::error_code ec;
  for (const auto& e : fs::directory_iterator(root / "chapters", ec)) {
    const std::string name = e.path().filename().string();
    if (e.is_directory() && name.size() > 3 && std::isdigit(static_cast<unsigned char>(name[0])) &&
        std::isdigit(static_cast<unsigned char>(name[1])) && name[2] == '-')
      slug_of[name.substr(0, 2)] = name;
  }
  std::vector<Job> jobs;
  for (const auto& [nn, slug] : slug_of) {
    const fs::path p = bin / ("chapter_" + nn);
    if (fs::exists(p, ec))
      jobs.push_back(Job{p, slug, {}, {}});
    else if (fs::exists(root / "chapters" / slug / "main.cpp", ec))
      unbuilt.push_back(fmt::format("not built: {} (so figures/{} is not drawn)", p.string(), slug));
  }
  if (fs::exists(bin / "gallery", ec)) jobs.push_back(Job{bin / "gallery", "gallery", {}, {}});
  return jobs;
}

// Runs the jobs, at most `parallel` at a time; fills in their exit statuses.
void run_all(std::vector<Job>& jobs, unsigned parallel) {
  std::vector<t2proc::Spec> specs;
  for (const auto& j : jobs) {
    t2proc::Spec s;
    s.argv = {j.program.string(), "--figures", j.out.string()};
    s.out = t2proc::Stream::discard;
    s.err_file = j.log;
    specs.push_back(std::move(s));
  }
  const auto results = t2proc::run_all(specs, static_cast<int>(parallel));
  for (std::size_t i = 0; i < jobs.size(); ++i) {
    if (!results[i].started)
      throw t2::BadInput(fmt::format("cannot run {}: {}", jobs[i].program.string(), results[i].error));
    jobs[i].status = results[i].exit_code;
  }
}

std::set<std::string> files_in(const fs::path& dir) {
  std::set<std::string> names;
  std::error_code ec;
  if (!fs::is_directory(dir, ec)) return names;
  for (const auto& e : fs::recursive_directory_iterator(dir, ec))
    if (e.is_regular_file()) names.insert(fs::relative(e.path(), dir).generic_string());
  return names;
}

struct Options {
  bool check = false;
  unsigned parallel = std::max(1u, std::thread::hardware_concurrency());
  fs::path root = T2_SOURCE_DIR;
};

int figures(const Options& o) {
  const bool check = o.check;
  const fs::path& root = o.root;
  const fs::path bin = bin_dir();
  std::vector<std::string> unbuilt;
  std::vector<Job> jobs = find_jobs(bin, root, unbuilt);
  if (jobs.empty())
    throw t2::BadInput(fmt::format("no chapter_NN or gallery program in {} (build them first)", bin.string()));

  // Each program writes into its own folder; in --check mode, a fresh temporary one.
  fs::path tmp;
  if (check) {
    std::string templ = (fs::temp_directory_path() / "t2-figures-XXXXXX").string();
    if (!::mkdtemp(templ.data())) throw std::runtime_error(fmt::format("mkdtemp: {}", std::strerror(errno)));
    tmp = templ;
  } else {
    tmp = fs::temp_directory_path() / fmt::format("t2-figures-logs-{}", ::getpid());
    fs::create_directories(tmp);
  }
  struct Cleanup {
    fs::path dir;
    ~Cleanup() {
      std::error_code ec;
      fs::remove_all(dir, ec);
    }
  } cleanup{tmp};
  for (auto& j : jobs) {
    j.out = check ? tmp / "figures" / j.slug : root / "figures" / j.slug;
    j.log = tmp / (j.slug + ".log");
    fs::create_directories(j.out);
  }
  run_all(jobs, o.parallel);

  int failed_programs = 0;
  for (const auto& j : jobs)
    if (j.status != 0) {
      ++failed_programs;
      fmt::print(stderr, "t2 figures: {} --figures {} failed (exit status {}):\n{}", j.program.string(),
                 j.out.string(), j.status, t2::read_file(j.log));
    }
  if (failed_programs > 0) return kFailed;

  if (!check) {
    for (const auto& u : unbuilt) fmt::print(stderr, "t2 figures: {}\n", u);
    std::size_t n = 0;
    for (const auto& j : jobs) n += files_in(j.out).size();
    fmt::print("t2 figures: {} programs, {} figures in {}\n", jobs.size(), n, (root / "figures").string());
    return kOk;
  }

  // Compare the fresh figures with the committed ones, folder by folder. A folder of figures/
  // that no program writes is all extra.
  std::vector<std::string> problems = unbuilt;
  std::set<std::string> slugs;
  for (const auto& j : jobs) slugs.insert(j.slug);
  std::error_code ec;
  for (const auto& e : fs::directory_iterator(root / "figures", ec))
    if (e.is_directory() && !fs::exists(root / "chapters" / e.path().filename() / "main.cpp", ec))
      slugs.insert(e.path().filename().string());  // a chapter's folder is compared only if its program ran
  std::size_t compared = 0;
  for (const auto& slug : slugs) {
    const fs::path fresh = tmp / "figures" / slug, committed = root / "figures" / slug;
    const auto want = files_in(fresh), have = files_in(committed);
    for (const auto& f : want) {
      ++compared;
      if (!have.count(f))
        problems.push_back(fmt::format("missing: figures/{}/{}", slug, f));
      else if (t2::read_file(fresh / f) != t2::read_file(committed / f))
        problems.push_back(fmt::format("differs: figures/{}/{}", slug, f));
    }
    for (const auto& f : have)
      if (!want.count(f)) problems.push_back(fmt::format("extra:   figures/{}/{} (no program writes it)", slug, f));
  }
  for (const auto& p : problems) fmt::print("{}\n", p);
  if (!problems.empty()) {
    fmt::print(stderr, "t2 figures --check: {} problems (build every program, then run t2 figures)\n", problems.size());
    return kFailed;
  }
  fmt::print("t2 figures --check: {} programs, {} figures, all up to date\n", jobs.size(), compared);
  return kOk;
}

Action setup(Arguments& app) {
  auto o = std::make_shared<Options>();
  app.description(
      "Runs, in parallel, every chapter program bin/chapter_NN next to this t2 (for each\n"
      "chapters/NN-slug/ of the source tree) with --figures figures/NN-slug, and\n"
      "bin/gallery with --figures figures/gallery. Programs only rewrite figures whose\n"
      "bytes changed.");
  app.add_flag("--check", o->check,
               "draw into a temporary folder instead and compare: print every figure\n"
               "that differs from the committed one or is missing, and every file of\n"
               "figures/ that no program writes; change nothing");
  app.add_option("--jobs,-j", o->parallel, "run at most N programs at a time (default: the number of cores)")
      ->check(Range(1, 256))
      ->type_name("N");
  app.add_option("--root", o->root, "the source tree (default: the one this t2 was built from)")->type_name("DIR");
  app.footer(
      "Exit status: 0 done (or, with --check, everything up to date); 1 a program failed\n"
      "or, with --check, some figure is out of date; 2 bad usage or no programs built.");
  return [o] { return figures(*o); };
}

}  // namespace cmd_figures

T2_COMMAND({"figures", "regenerate every figure (chapters and gallery), or check them", cmd_figures::setup});

}  // namespace t2cli
