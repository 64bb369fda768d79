// Judging: run_exercise (see grader_core.hpp). For each test two processes run side by side and
// talk through two pipes: the checker (trusted: the tests and their oracles, never linked with
// student code) sends the calls and decides the verdict; the driver (the student's functions,
// in the sandbox) only answers. How the driver ended names the verdict when it stopped answering.
#include <fcntl.h>
#include <signal.h>
#include <stdlib.h>
#include <sys/stat.h>
#include <unistd.h>

#include <chrono>
#include <memory>
#include <sstream>
#include <thread>

#include <fmt/format.h>

#include "grader_build.hpp"
#include "grader_core.hpp"
#include "grader_intake.hpp"
#include "process.hpp"

namespace t2grader {

namespace {

using Clock = std::chrono::steady_clock;

// The run's temporary tree: the grader's and the sandbox user's only (0700, or 0710 with the
// sandbox user's group when the grader is root and the sandbox another uid), removed at the end
// of the run, or by a watcher process when the grader is killed.
struct TempDir {
  fs::path path;
  std::unique_ptr<t2proc::RemoveWhenGone> guard;
  TempDir() {
    std::string t = (fs::temp_directory_path() / "t2grade-XXXXXX").string();
    if (!mkdtemp(t.data())) throw GraderError("cannot create a temporary directory");
    path = t;
    guard = std::make_unique<t2proc::RemoveWhenGone>(path);
    if (::geteuid() == 0) {
      if (::chown(path.c_str(), 0, sandbox_uid()) != 0 || ::chmod(path.c_str(), 0710) != 0)
        throw GraderError("cannot give the temporary directory to the sandbox's group");
    }
  }
  ~TempDir() {
    std::error_code ec;
    fs::remove_all(path, ec);
  }
};

std::vector<std::string> list_tests(const fs::path& checker) {
  t2proc::Spec s;
  s.argv = {checker.string(), "--t2-list"};
  s.limits.wall_seconds = 60;
  const auto r = t2proc::run(s);
  if (!r.ok()) throw GraderError("internal error: cannot list the tests of " + checker.string() + ": " + r.error + r.err);
  std::vector<std::string> names;
  std::istringstream in(r.out);
  for (std::string l; std::getline(in, l);)
    if (!l.empty()) names.push_back(l);
  return names;
}

std::string signal_words(int sig) {
  switch (sig) {
    case SIGSEGV:
      return "crashed with a segmentation fault (SIGSEGV): a bad pointer or index, or a stack overflow from runaway recursion";
    case SIGBUS: return "crashed with a bus error (SIGBUS): a bad pointer";
    case SIGABRT: return "aborted (SIGABRT): an assert failed, or std::terminate was called";
    case SIGFPE: return "crashed with an arithmetic error (SIGFPE): an integer division by zero?";
    case SIGXCPU: return "used more than its CPU time and was stopped: an infinite loop?";
    case SIGXFSZ: return "wrote a file larger than allowed and was stopped";
    case SIGKILL: return "was killed (SIGKILL): it exceeded its memory or process limit";
    default: return fmt::format("was killed by signal {} ({})", sig, strsignal(sig));
  }
}

struct Pipe {
  int r = -1, w = -1;
  Pipe() {
    int p[2];
    if (pipe2(p, O_CLOEXEC) != 0) throw GraderError("cannot create a pipe");
    r = p[0];
    w = p[1];
  }
};

// One test: the checker and the driver side by side.
void judge_one(TestResult& t, const fs::path& checker, const fs::path& driver, const TrustedParts& parts, int cpu_s,
               int memory_mb, double wall) {
  Pipe calls, answers;
  t2proc::Spec c;
  c.argv = {checker.string(), fmt::format("--t2-calls={}", calls.w), fmt::format("--t2-answers={}", answers.r),
            "--gtest_filter=" + t.name};
  c.keep_fds = c.close_in_parent = {calls.w, answers.r};
  c.limits.wall_seconds = wall + 10;
  c.limits.output_bytes = 16 << 10;
  c.err = t2proc::Stream::discard;
  SandboxRun d;
  d.argv = {"/t2/driver", fmt::format("--t2-calls={}", calls.r), fmt::format("--t2-answers={}", answers.w)};
  d.copied = {{driver, "/t2/driver"}};  // a copy: no host path in the sandbox's mountinfo
  // No /usr, in either build: the driver's shared libraries only (GMP, Boost, CGAL ... are not
  // there to dlopen).
  d.system = false;
  d.read_only = parts.runtime;
  d.handover_fds = {calls.r, answers.w};
  d.limits.cpu_seconds = cpu_s;
  d.tree_cpu_seconds = cpu_s;  // and for all its processes together (forked workers included)
  d.limits.wall_seconds = wall;
  d.limits.memory_bytes = static_cast<std::uint64_t>(memory_mb) << 20;
#if defined(T2_SANITIZE)
  d.limits.memory_bytes = 0;  // the sanitizers' shadow memory needs terabytes of address space
#endif
  d.limits.file_bytes = 16u << 20;
  d.tree_memory_bytes = (static_cast<std::uint64_t>(memory_mb) + 128) << 20;
  d.tmp_bytes = 64u << 20;
  d.out = d.err = t2proc::Stream::discard;  // printing costs nothing and counts for nothing
  const Prepared dp = prepare_sandboxed(d);
  // Side by side; once the checker has said PASS, FAIL or LIMIT the verdict is its own, whatever
  // the driver does next, so a driver still running then (it shut its pipes and waits, as
  // exercises/_hostile/constructor-priority does) is stopped instead of waited for to its wall
  // clock. After GONE how the driver ends names the verdict: it runs to its end or its limits.
  t2proc::Result cr, dr;
  std::thread answering([&] { dr = t2proc::run(dp.spec); });
  cr = t2proc::run(c);
  std::istringstream rec(cr.out);
  std::string verdict, messages;
  std::getline(rec, verdict);
  if (dp.kill && cr.ok() && (verdict == "PASS" || verdict == "FAIL" || verdict == "LIMIT")) dp.kill();
  answering.join();
  messages.assign(std::istreambuf_iterator<char>(rec), {});
  if (verdict == "PASS" && cr.ok()) {
    t.passed = true;
    t.what = "passed";
  } else if (verdict == "LIMIT") {
    t.what = "output limit";
  } else if (verdict == "GONE" || !cr.ok()) {
    // Through bubblewrap the CPU limit's SIGXCPU arrives as the exit status 128 + SIGXCPU; a run
    // that lasted at least the CPU limit tells it from a deliberate, early exit(152).
    const bool out_of_cpu = *dp.out_of_cpu || dr.signal == SIGXCPU ||
                            (dr.exit_code == 128 + SIGXCPU && dr.wall_seconds >= 0.9 * cpu_s);
    if (dr.timed_out || out_of_cpu || (cr.timed_out && !dr.ok())) {
      t.what = "timed out";
      if (!t.hidden)
        t.detail = out_of_cpu ? fmt::format("used its {} s of CPU time and was stopped (an infinite loop?)", cpu_s)
                              : fmt::format("still running after {:.0f} s (an infinite loop, or waiting for input?)", wall);
    } else if (dr.signal != 0 || dr.exit_code > 128) {
      // Through bubblewrap a crash shows as the exit status 128 + signal (an exit(129..192) looks the same).
      t.what = "crashed";
      if (!t.hidden)
        t.detail = dr.signal ? "your code " + signal_words(dr.signal)
                             : fmt::format("your code {} (exit status {})", signal_words(dr.exit_code - 128), dr.exit_code);
    } else {
      t.what = "failed";
      if (!t.hidden)
        t.detail = fmt::format("your code stopped before the test finished (exit status {}): does it call exit() or abort()?",
                               dr.exit_code);
    }
  } else {
    t.what = "failed";
    if (!t.hidden) {
      t.detail = messages;
      if (messages.find("not implemented yet") != std::string::npos) t.what = "failed: not implemented yet";
    }
  }
  if (!t.hidden && !t.detail.empty() && t.what != "failed" && t.what.rfind("failed:", 0) != 0)
    t.what += ": " + t.detail.substr(0, t.detail.find('\n')), t.detail.clear();
}

}  // namespace

double Report::score() const {
  double s = 0;
  for (const auto& t : tests) s += t.passed ? t.max_score : 0;
  return s;
}
double Report::max_score() const {
  double s = 0;
  for (const auto& t : tests) s += t.max_score;
  return s;
}

Report run_exercise(const Exercise& ex, const fs::path& submission_dir, const RunOptions& opt) {
  Report rep;
  rep.exercise = ex;
  const auto start = Clock::now();
  auto remaining = [&] { return opt.overall_limit - std::chrono::duration<double>(Clock::now() - start).count(); };
  auto say = [&](const std::string& s) {
    if (opt.verbose) fmt::print(stderr, "{}\n", s);
  };
  if (opt.include_hidden && !fs::exists(ex.hidden_tests()))
    throw GraderError(fmt::format("{} has no hidden tests (is this a student release?): grading needs the instructor's tree; "
                                  "`t2 check {}` runs the public tests",
                                  ex.id, ex.id.substr(0, ex.id.find('-'))));
  library_archive();
  TempDir tmp;
  say("building the tests (cached after the first time)");
  const TrustedParts parts = build_trusted(ex, opt.include_hidden, tmp.path);
  std::vector<fs::path> secrets = {ex.solution_dir() / ex.source, parts.checker_public};
  if (opt.include_hidden) secrets.push_back(ex.hidden_tests());
  const Sandbox& box = sandbox(parts.probe, secrets);
  rep.protection = box.description;
  for (const auto& n : list_tests(parts.checker_public)) rep.tests.push_back({n, false, false, ex.points_of(n), "", ""});
  if (opt.include_hidden)
    for (const auto& n : list_tests(parts.checker_hidden)) rep.tests.push_back({n, true, false, ex.points_of(n), "", ""});
  if (rep.tests.empty()) throw GraderError("internal error: no tests found for " + ex.id);
  if (!box.works) throw GraderError("refusing to run student code: " + box.description);
  // Grading (hidden tests, someone else's code): the whole tree's memory and CPU time must be
  // bounded. Without root there is no cgroup: per-process limits only, and /tmp's size.
  if (opt.include_hidden && !box.tree_bounded && !opt.unsafe)
    throw GraderError("refusing to grade: no cgroup bounds the memory and CPU time of a submission's whole process "
                      "tree (the grader needs root for that: run it as root, as in the Gradescope container); "
                      "--unsafe grades anyway, with per-process limits only (" + box.description + ")");

  auto fail_all = [&](const std::string& what) {
    for (auto& t : rep.tests) t.what = what;
    return rep;
  };
  if (const std::string why = take_in(ex, submission_dir, tmp.path / "src"); !why.empty()) {
    rep.compiler_output = why;
    return fail_all("not run: the submission was refused");
  }
  say("compiling " + ex.source + " in the sandbox");
  const StudentBuild b = build_student(ex, parts, tmp.path / "src", tmp.path / "out",
                                       std::min<double>(opt.compile_limit, std::max(1.0, remaining())));
  if (!b.ok) {
    rep.compiler_output = b.messages;
    rep.overall_timeout = b.timed_out && remaining() <= 0;
    return fail_all(b.refused ? "not run: " + b.messages.substr(0, b.messages.find(';'))
                              : b.timed_out ? "not run: compiling ran out of time" : "not run: the code does not compile");
  }
  rep.compiled = true;
  const int cpu = opt.time_limit > 0 ? opt.time_limit : ex.time_limit;
  int k = 0;
  for (auto& t : rep.tests) {
    ++k;
    const double left = remaining();
    if (left <= 1) {
      rep.overall_timeout = true;
      t.what = "not run: the overall time limit of the grading run ran out";
      continue;
    }
    say(fmt::format("running {} ({}/{})", t.name, k, rep.tests.size()));
    judge_one(t, t.hidden ? parts.checker_hidden : parts.checker_public, b.driver, parts, cpu, ex.memory_mb,
              std::min(opt.wall_limit > 0 ? double(opt.wall_limit) : 2.0 * cpu + 2, left));
  }
  return rep;
}

}  // namespace t2grader
