// The one process module (tools/common/process.hpp): exit codes, signals, the wall-clock limit
// that kills a whole process group, bounded output that never blocks the child, stdin, env, cwd,
// resource limits and run_all's order and parallelism.
#include <gtest/gtest.h>
#include <fcntl.h>
#include <signal.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <string>

#include "process.hpp"

namespace {

namespace fs = std::filesystem;
using t2proc::Result;
using t2proc::Spec;
using t2proc::Stream;

Spec sh(const std::string& script) {
  Spec s;
  s.argv = {"/bin/sh", "-c", script};
  return s;
}

// Running (a zombie waiting for its reaper counts as ended).
bool alive(pid_t pid) {
  std::ifstream in("/proc/" + std::to_string(pid) + "/stat");
  std::string stat;
  if (!std::getline(in, stat)) return false;
  const auto close = stat.rfind(')');
  return close != std::string::npos && close + 2 < stat.size() && stat[close + 2] != 'Z' && stat[close + 2] != 'X';
}

TEST(Process, ExitCodesAreReportedAsSuch) {
  for (int code : {0, 1, 2, 77, 129, 137, 192, 255}) {
    const Result r = t2proc::run(sh("exit " + std::to_string(code)));
    ASSERT_TRUE(r.started) << r.error;
    EXPECT_EQ(r.exit_code, code);
    EXPECT_EQ(r.signal, 0) << "exit status " << code << " is not a signal";
    EXPECT_EQ(r.ok(), code == 0);
  }
}

TEST(Process, SignalsAreReportedAsSuch) {
  for (int sig : {SIGSEGV, SIGABRT, SIGKILL, SIGTERM}) {
    const Result r = t2proc::run(sh("kill -" + std::to_string(sig) + " $$"));
    ASSERT_TRUE(r.started);
    EXPECT_EQ(r.signal, sig);
    EXPECT_EQ(r.exit_code, -1);
    EXPECT_FALSE(r.ok());
  }
}

TEST(Process, MissingProgramIsNotStarted) {
  Spec s;
  s.argv = {"t2-no-such-program-anywhere"};
  const Result r = t2proc::run(s);
  EXPECT_FALSE(r.started);
  EXPECT_NE(r.error.find("t2-no-such-program-anywhere"), std::string::npos);
  s.argv = {"/nonexistent/prog"};
  EXPECT_FALSE(t2proc::run(s).started);
}

TEST(Process, CapturesBothStreamsSeparately) {
  const Result r = t2proc::run(sh("echo out; echo err >&2"));
  EXPECT_EQ(r.out, "out\n");
  EXPECT_EQ(r.err, "err\n");
  Spec d = sh("echo out; echo err >&2");
  d.out = Stream::discard;
  d.err = Stream::discard;
  const Result q = t2proc::run(d);
  EXPECT_TRUE(q.ok());
  EXPECT_EQ(q.out, "");
  EXPECT_EQ(q.err, "");
}

TEST(Process, WallTimeoutKillsTheWholeGroupIncludingGrandchildren) {
  const fs::path pidfile = fs::temp_directory_path() / ("t2proc-pid-" + std::to_string(::getpid()));
  // A grandchild (in the background, its stdout not ours) that would outlive its parent.
  Spec s = sh("sh -c 'echo $$ > " + pidfile.string() + "; exec sleep 60' >/dev/null 2>&1 & sleep 60");
  s.limits.wall_seconds = 0.5;
  const auto t0 = std::chrono::steady_clock::now();
  const Result r = t2proc::run(s);
  const double took = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  EXPECT_TRUE(r.timed_out);
  EXPECT_EQ(r.signal, SIGKILL);
  EXPECT_LT(took, 10.0);
  std::ifstream in(pidfile);
  pid_t grandchild = 0;
  in >> grandchild;
  fs::remove(pidfile);
  ASSERT_GT(grandchild, 0);
  for (int i = 0; i < 100 && alive(grandchild); ++i) ::usleep(10000);
  EXPECT_FALSE(alive(grandchild)) << "the grandchild survived the timeout";
}

TEST(Process, GroupIsEndedWhenTheChildExits) {
  const fs::path pidfile = fs::temp_directory_path() / ("t2proc-left-" + std::to_string(::getpid()));
  Spec s = sh("sh -c 'echo $$ > " + pidfile.string() + "; exec sleep 60' >/dev/null 2>&1 & sleep 0.2; exit 3");
  const Result r = t2proc::run(s);
  EXPECT_EQ(r.exit_code, 3);
  EXPECT_FALSE(r.timed_out);
  std::ifstream in(pidfile);
  pid_t left = 0;
  in >> left;
  fs::remove(pidfile);
  ASSERT_GT(left, 0);
  for (int i = 0; i < 100 && alive(left); ++i) ::usleep(10000);
  EXPECT_FALSE(alive(left));
}

TEST(Process, OutputCapKeepsThePrefixWithoutBlockingTheChild) {
  // 8 MB on each stream (far beyond a pipe's buffer), then a normal exit.
  Spec s = sh("head -c 8000000 /dev/zero | tr '\\0' a; head -c 8000000 /dev/zero | tr '\\0' b >&2; exit 0");
  s.limits.output_bytes = 1000;
  s.limits.wall_seconds = 60;
  const Result r = t2proc::run(s);
  EXPECT_TRUE(r.ok());
  EXPECT_FALSE(r.timed_out);
  EXPECT_EQ(r.out, std::string(1000, 'a'));
  EXPECT_EQ(r.err, std::string(1000, 'b'));
  EXPECT_TRUE(r.out_truncated);
  EXPECT_TRUE(r.err_truncated);
  const Result small = t2proc::run(sh("echo hi"));
  EXPECT_FALSE(small.out_truncated);
}

TEST(Process, StdinDataIsWrittenThenClosed) {
  Spec s;
  s.argv = {"wc", "-c"};
  s.stdin_data = std::string(300000, 'x');  // more than a pipe holds: fed while the child reads
  const Result r = t2proc::run(s);
  EXPECT_TRUE(r.ok());
  EXPECT_EQ(std::stol(r.out), 300000);
  Spec e;
  e.argv = {"cat"};
  EXPECT_EQ(t2proc::run(e).out, "") << "no stdin data: /dev/null";
  // A child that does not read its input does not hurt the caller (no SIGPIPE).
  Spec deaf = sh("exit 0");
  deaf.stdin_data = std::string(1 << 20, 'y');
  EXPECT_TRUE(t2proc::run(deaf).ok());
}

TEST(Process, InheritedStdinIsTheCallersAndTheChildStaysInItsGroup) {
  // Make fd 0 of this process a file for a moment, as `t2 run 05 < in` does.
  const fs::path in = fs::temp_directory_path() / ("t2-process-stdin-" + std::to_string(::getpid()));
  std::ofstream(in) << "from the caller\n";
  const int saved = ::dup(0);
  ASSERT_GE(saved, 0);
  const int fd = ::open(in.c_str(), O_RDONLY);
  ASSERT_GE(fd, 0);
  ASSERT_EQ(::dup2(fd, 0), 0);
  ::close(fd);
  Spec s = sh("cat; cut -d' ' -f5 /proc/$$/stat");  // field 5: the process group
  s.inherit_stdin = true;
  s.stdin_data = "ignored";  // the caller's stdin wins
  const Result r = t2proc::run(s);
  ::dup2(saved, 0);
  ::close(saved);
  fs::remove(in);
  ASSERT_TRUE(r.ok()) << r.err;
  EXPECT_EQ(r.out.substr(0, r.out.find('\n') + 1), "from the caller\n");
  EXPECT_EQ(std::stol(r.out.substr(r.out.find('\n') + 1)), static_cast<long>(::getpgrp()))
      << "a child reading the caller's terminal must be in the caller's (foreground) group";
}

TEST(Process, EnvironmentIsExactlyTheGivenOne) {
  Spec s;
  s.argv = {"/usr/bin/env"};
  s.env = std::vector<std::string>{"A=1", "B=two words"};
  EXPECT_EQ(t2proc::run(s).out, "A=1\nB=two words\n");
  ::setenv("T2PROC_INHERITED", "yes", 1);
  Spec inherit = sh("echo $T2PROC_INHERITED");
  EXPECT_EQ(t2proc::run(inherit).out, "yes\n");
}

TEST(Process, RunsInTheGivenFolder) {
  Spec s;
  s.argv = {"pwd"};
  s.cwd = "/usr";
  EXPECT_EQ(t2proc::run(s).out, "/usr\n");
  s.cwd = "/nonexistent-folder";
  EXPECT_FALSE(t2proc::run(s).started);
}

TEST(Process, StderrToAFile) {
  const fs::path f = fs::temp_directory_path() / ("t2proc-err-" + std::to_string(::getpid()));
  Spec s = sh("echo to-file >&2; echo to-out");
  s.err_file = f;
  const Result r = t2proc::run(s);
  EXPECT_EQ(r.out, "to-out\n");
  EXPECT_EQ(r.err, "");
  std::ifstream in(f);
  std::string line;
  std::getline(in, line);
  EXPECT_EQ(line, "to-file");
  fs::remove(f);
}

TEST(Process, KeptFdsAreInheritedOthersClosed) {
  int p[2];
  ASSERT_EQ(::pipe(p), 0);
  int q[2];
  ASSERT_EQ(::pipe(q), 0);  // not kept: the child must not see it
  Spec s = sh("echo kept >&" + std::to_string(p[1]) + "; echo leaked >&" + std::to_string(q[1]) + " 2>/dev/null; exit 0");
  s.keep_fds = {p[1]};
  const Result r = t2proc::run(s);
  ::close(p[1]);
  ::close(q[1]);
  EXPECT_TRUE(r.started);
  char buf[64] = {};
  EXPECT_EQ(::read(p[0], buf, sizeof buf), 5);
  EXPECT_EQ(std::string(buf, 5), "kept\n");
  EXPECT_EQ(::read(q[0], buf, sizeof buf), 0) << "an fd that was not kept reached the child";
  ::close(p[0]);
  ::close(q[0]);
}

TEST(Process, TwoChildrenTalkThroughPipesAndSeeEachOthersEnd) {
  // a → b through one pipe; the caller hands both ends over, so b sees EOF when a ends.
  int p[2];
  ASSERT_EQ(::pipe2(p, O_CLOEXEC), 0);
  Spec a = sh("echo hello >&" + std::to_string(p[1]));
  a.keep_fds = a.close_in_parent = {p[1]};
  Spec b = sh("cat <&" + std::to_string(p[0]));
  b.keep_fds = b.close_in_parent = {p[0]};
  b.limits.wall_seconds = 20;
  const auto rs = t2proc::run_all({a, b}, 2);
  EXPECT_TRUE(rs[0].ok());
  EXPECT_TRUE(rs[1].ok()) << "b waited for an EOF that never came";
  EXPECT_FALSE(rs[1].timed_out);
  EXPECT_EQ(rs[1].out, "hello\n");
  EXPECT_EQ(::fcntl(p[0], F_GETFD), -1) << "handed-over fds are closed in the caller";
}

TEST(Process, ResourceLimits) {
  Spec cpu = sh("while :; do :; done");
  cpu.limits.cpu_seconds = 1;
  cpu.limits.wall_seconds = 300;
  const Result c = t2proc::run(cpu);
  EXPECT_EQ(c.signal, SIGXCPU);
  EXPECT_FALSE(c.timed_out);
  EXPECT_GE(c.cpu_seconds, 0.5);  // RLIMIT_CPU fires on a tick: rusage may read a little under 1 s

  Spec big = sh("head -c 100000 /dev/zero > " + (fs::temp_directory_path() / ("t2proc-f-" + std::to_string(::getpid()))).string());
  big.limits.file_bytes = 1000;
  const Result b = t2proc::run(big);
  EXPECT_FALSE(b.ok());
  fs::remove(fs::temp_directory_path() / ("t2proc-f-" + std::to_string(::getpid())));

  Spec mem;
  mem.argv = {"/usr/bin/python3", "-c", "x = bytearray(400 * 1024 * 1024)"};
  mem.limits.memory_bytes = 200u << 20;
  mem.err = Stream::discard;
  if (std::filesystem::exists(mem.argv[0])) {
    EXPECT_FALSE(t2proc::run(mem).ok());
  }
}

TEST(Process, RunAllKeepsOrderAndRunsInParallel) {
  std::vector<Spec> specs;
  for (int i = 0; i < 6; ++i) specs.push_back(sh("sleep 0.5; echo " + std::to_string(i)));
  const auto t0 = std::chrono::steady_clock::now();
  const auto rs = t2proc::run_all(specs, 3);
  const double took = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  ASSERT_EQ(rs.size(), 6u);
  for (int i = 0; i < 6; ++i) EXPECT_EQ(rs[static_cast<size_t>(i)].out, std::to_string(i) + "\n");
  EXPECT_LT(took, 2.5) << "6 runs of 0.5 s, 3 at a time, took " << took << " s: not parallel";
  EXPECT_GE(took, 0.95) << "at most 3 at once";
  EXPECT_TRUE(t2proc::run_all({}, 4).empty());
}

}  // namespace
