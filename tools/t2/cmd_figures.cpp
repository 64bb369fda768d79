// t2 figures: regenerate every figure of the book (chapter programs and the gallery), or check
// that the committed figures are what the programs draw.
#include <fcntl.h>
#include <fmt/format.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstring>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <optional>
#include <set>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "command.hpp"
#include "t2/error.hpp"

extern char** environ;

namespace t2cli {
namespace {

namespace fs = std::filesystem;

/// One program that writes the figures of one folder figures/<slug>.
struct Job {
  fs::path program;  // bin/chapter_NN or bin/gallery
  std::string slug;  // NN-slug or gallery
  fs::path out;      // the folder given with --figures
  fs::path log;      // its stderr
  pid_t pid = -1;
  int status = -1;   // exit status, -1 when it did not exit normally
};

fs::path bin_dir() {
  std::error_code ec;
  const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
  if (ec) throw t2::BadInput("cannot find the folder of the t2 program (/proc/self/exe)");
  return exe.parent_path();
}

std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
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

pid_t spawn(Job& j) {
  const std::string prog = j.program.string(), out = j.out.string(), log = j.log.string();
  posix_spawn_file_actions_t fa;
  posix_spawn_file_actions_init(&fa);
  posix_spawn_file_actions_addopen(&fa, 0, "/dev/null", O_RDONLY, 0);
  posix_spawn_file_actions_addopen(&fa, 1, "/dev/null", O_WRONLY, 0);
  posix_spawn_file_actions_addopen(&fa, 2, log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  std::vector<char*> argv = {const_cast<char*>(prog.c_str()), const_cast<char*>("--figures"),
                             const_cast<char*>(out.c_str()), nullptr};
  pid_t pid = -1;
  const int rc = posix_spawn(&pid, prog.c_str(), &fa, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&fa);
  if (rc != 0) throw t2::BadInput(fmt::format("cannot run {}: {}", prog, std::strerror(rc)));
  return pid;
}

// Runs the jobs, at most `parallel` at a time; fills in their exit statuses.
void run_all(std::vector<Job>& jobs, unsigned parallel) {
  std::size_t next = 0, running = 0;
  while (next < jobs.size() || running > 0) {
    while (next < jobs.size() && running < parallel) {
      jobs[next].pid = spawn(jobs[next]);
      ++next;
      ++running;
    }
    int raw = 0;
    const pid_t pid = ::waitpid(-1, &raw, 0);
    if (pid < 0) {
      if (errno == EINTR) continue;
      throw std::runtime_error(fmt::format("waitpid: {}", std::strerror(errno)));
    }
    for (auto& j : jobs)
      if (j.pid == pid) {
        j.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
        --running;
      }
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

int run(Args args) {
  bool check = false;
  unsigned parallel = std::max(1u, std::thread::hardware_concurrency());
  fs::path root = T2_SOURCE_DIR;
  for (std::size_t i = 0; i < args.size(); ++i) {
    const std::string& a = args[i];
    if (a == "--check") {
      check = true;
    } else if (a == "--jobs" || a == "-j") {
      if (i + 1 == args.size()) throw UsageError(fmt::format("{} needs a number", a));
      const std::string& v = args[++i];
      char* end = nullptr;
      const long n = std::strtol(v.c_str(), &end, 10);
      if (v.empty() || *end != '\0' || n < 1 || n > 256)
        throw UsageError(fmt::format("--jobs needs a number from 1 to 256, not '{}'", v));
      parallel = static_cast<unsigned>(n);
    } else if (a == "--root") {
      if (i + 1 == args.size()) throw UsageError("--root needs a folder");
      root = args[++i];
    } else {
      throw UsageError(fmt::format("unknown argument '{}'", a));
    }
  }
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
  run_all(jobs, parallel);

  int failed_programs = 0;
  for (const auto& j : jobs)
    if (j.status != 0) {
      ++failed_programs;
      fmt::print(stderr, "t2 figures: {} --figures {} failed (exit status {}):\n{}", j.program.string(),
                 j.out.string(), j.status, slurp(j.log));
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
      else if (slurp(fresh / f) != slurp(committed / f))
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

}  // namespace

T2_COMMAND({"figures", "regenerate every figure (chapters and gallery), or check them",
            "Usage: t2 figures [--check] [--jobs N] [--root DIR]\n"
            "\n"
            "Runs, in parallel, every chapter program bin/chapter_NN next to this t2 (for each\n"
            "chapters/NN-slug/ of the source tree) with --figures figures/NN-slug, and\n"
            "bin/gallery with --figures figures/gallery. Programs only rewrite figures whose\n"
            "bytes changed.\n"
            "\n"
            "  --check    draw into a temporary folder instead and compare: print every figure\n"
            "             that differs from the committed one or is missing, and every file of\n"
            "             figures/ that no program writes; change nothing\n"
            "  --jobs N   run at most N programs at a time (default: the number of cores)\n"
            "  --root DIR the source tree (default: the one this t2 was built from)\n"
            "\n"
            "Exit status: 0 done (or, with --check, everything up to date); 1 a program failed\n"
            "or, with --check, some figure is out of date; 2 bad usage or no programs built.\n",
            run});

}  // namespace t2cli
