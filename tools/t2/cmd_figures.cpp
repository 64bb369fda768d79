// t2 figures: runs every chapter program (and the gallery) to regenerate figures/, or checks
// that the committed figures are up to date.
#include <fmt/format.h>
#include <spawn.h>
#include <sys/wait.h>
#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "command.hpp"

extern char** environ;

namespace t2cli {
namespace {

namespace fs = std::filesystem;

const char* const kHelp =
    "Usage: t2 figures [--check] [--jobs N] [--source DIR]\n"
    "\n"
    "Runs every chapter program (bin/chapter_NN, next to this t2) and the gallery program\n"
    "(bin/gallery), N at a time (default 2), each writing its figures into figures/NN-slug/ (the\n"
    "gallery into figures/gallery/) of the repository DIR (default: the one t2 was built from).\n"
    "\n"
    "With --check, the programs write into a temporary directory instead, and t2 figures exits 1\n"
    "listing every figure whose committed copy differs or is missing, and every committed figure\n"
    "that no program writes any more. Exit 0: the committed figures are up to date.\n";

struct Job {
  std::string name;     // chapter_01, gallery
  fs::path program;     // the executable
  std::string slug;     // 01-t2-plane, gallery
  fs::path out;         // where it writes
  fs::path log;         // its stdout and stderr
  pid_t pid = 0;
  int status = -1;
};

std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

pid_t start(const Job& j) {
  posix_spawn_file_actions_t fa;
  posix_spawn_file_actions_init(&fa);
  posix_spawn_file_actions_addopen(&fa, 1, j.log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  posix_spawn_file_actions_adddup2(&fa, 1, 2);
  posix_spawn_file_actions_addopen(&fa, 0, "/dev/null", O_RDONLY, 0);
  const std::string prog = j.program.string(), flag = "--figures", out = j.out.string();
  char* argv[] = {const_cast<char*>(prog.c_str()), const_cast<char*>(flag.c_str()), const_cast<char*>(out.c_str()),
                  nullptr};
  pid_t pid = 0;
  const int rc = posix_spawn(&pid, prog.c_str(), &fa, nullptr, argv, environ);
  posix_spawn_file_actions_destroy(&fa);
  if (rc != 0) throw std::runtime_error("t2 figures: cannot run " + prog);
  return pid;
}

/// Every regular file under dir, relative to it.
std::vector<std::string> files_under(const fs::path& dir) {
  std::vector<std::string> v;
  if (!fs::is_directory(dir)) return v;
  for (const auto& e : fs::recursive_directory_iterator(dir))
    if (e.is_regular_file()) v.push_back(fs::relative(e.path(), dir).generic_string());
  std::sort(v.begin(), v.end());
  return v;
}

int run(Args args) {
  bool check = false;
  int jobs = 2;
  fs::path source = T2_SOURCE_DIR;
  for (std::size_t i = 0; i < args.size(); ++i) {
    if (args[i] == "--check") {
      check = true;
    } else if (args[i] == "--jobs" || args[i] == "-j") {
      if (i + 1 >= args.size()) throw UsageError("--jobs needs a number");
      jobs = std::atoi(args[++i].c_str());
      if (jobs < 1 || jobs > 256) throw UsageError("--jobs wants a number from 1 to 256");
    } else if (args[i] == "--source") {
      if (i + 1 >= args.size()) throw UsageError("--source needs a directory");
      source = args[++i];
    } else {
      throw UsageError("unknown argument " + args[i]);
    }
  }
  const fs::path bin = fs::read_symlink("/proc/self/exe").parent_path();

  // The programs: chapter_NN for every chapters/NN-slug/ that has a main.cpp, and the gallery.
  std::vector<Job> todo;
  if (fs::is_directory(source / "chapters"))
    for (const auto& e : fs::directory_iterator(source / "chapters")) {
      const std::string slug = e.path().filename().string();
      if (!e.is_directory() || slug.size() < 4 || slug[2] != '-' || !fs::exists(e.path() / "main.cpp")) continue;
      todo.push_back({"chapter_" + slug.substr(0, 2), bin / ("chapter_" + slug.substr(0, 2)), slug, {}, {}});
    }
  if (fs::exists(source / "gallery" / "main.cpp")) todo.push_back({"gallery", bin / "gallery", "gallery", {}, {}});
  std::sort(todo.begin(), todo.end(), [](const Job& a, const Job& b) { return a.name < b.name; });
  for (const auto& j : todo)
    if (!fs::exists(j.program))
      throw std::runtime_error(fmt::format("t2 figures: {} is not built (cmake --build <build dir> --target {})",
                                           j.program.string(), j.name));

  char tmpl[] = "/tmp/t2-figures-XXXXXX";
  if (!mkdtemp(tmpl)) throw std::runtime_error("t2 figures: cannot create a temporary directory");
  const fs::path tmp = tmpl;
  for (auto& j : todo) {
    j.out = check ? tmp / j.slug : source / "figures" / j.slug;
    j.log = tmp / (j.name + ".log");
  }

  // Run them, `jobs` at a time.
  std::size_t next = 0, running = 0;
  std::map<pid_t, Job*> live;
  while (next < todo.size() || running > 0) {
    while (running < static_cast<std::size_t>(jobs) && next < todo.size()) {
      Job& j = todo[next++];
      j.pid = start(j);
      live[j.pid] = &j;
      ++running;
    }
    int status = 0;
    const pid_t pid = waitpid(-1, &status, 0);
    if (pid < 0) break;
    if (auto it = live.find(pid); it != live.end()) {
      it->second->status = status;
      live.erase(it);
      --running;
    }
  }

  int failed = 0;
  for (const auto& j : todo) {
    if (WIFEXITED(j.status) && WEXITSTATUS(j.status) == 0) continue;
    ++failed;
    fmt::print(stderr, "t2 figures: {} failed (status {}):\n{}", j.name,
               WIFEXITED(j.status) ? WEXITSTATUS(j.status) : 128 + WTERMSIG(j.status), slurp(j.log));
  }

  int stale = 0;
  if (check) {
    for (const auto& j : todo) {
      const fs::path committed = source / "figures" / j.slug;
      const auto fresh = files_under(j.out), old = files_under(committed);
      for (const auto& f : fresh) {
        if (!fs::exists(committed / f)) {
          fmt::print("missing: figures/{}/{} (written by {}, not committed)\n", j.slug, f, j.name);
          ++stale;
        } else if (slurp(committed / f) != slurp(j.out / f)) {
          fmt::print("differs: figures/{}/{} (run t2 figures and commit it)\n", j.slug, f);
          ++stale;
        }
      }
      for (const auto& f : old)
        if (!std::binary_search(fresh.begin(), fresh.end(), f)) {
          fmt::print("not written any more: figures/{}/{} (delete it?)\n", j.slug, f);
          ++stale;
        }
    }
  }
  std::error_code ec;
  fs::remove_all(tmp, ec);
  if (failed) return kFailed;
  if (stale) {
    fmt::print("{} figure(s) out of date\n", stale);
    return kFailed;
  }
  fmt::print("{} {} program(s): figures {}\n", check ? "checked" : "ran", todo.size(),
             check ? "up to date" : "written");
  return kOk;
}

}  // namespace

T2_COMMAND({"figures", "regenerate every figure (chapters and gallery), or --check them", kHelp, run})

}  // namespace t2cli
