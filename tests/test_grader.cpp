// The grader against hostile submissions, its reports (results.json, t2 check) and its sandbox
// (the releases: tests/test_grader_release.cpp).
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <thread>
#include <cctype>
#include <chrono>
#include <iterator>
#include <map>

#include <filesystem>
#include <fstream>
#include <set>
#include <string>

#include "../exercises/harness/grader_testing.hpp"

namespace {

namespace fs = std::filesystem;
using namespace t2::grader_testing;

const std::string kTool = T2_TOOL;
const fs::path kSource = T2_SOURCE_DIR;
const fs::path kExercises = kSource / "exercises";
const fs::path kHostile = kExercises / "_hostile";

// These tests also run under the ASan preset: the tool is then sanitized, and so are the
// programs it builds (the kernel archive needs the sanitizers' runtimes, which the driver links
// statically, so that its sandbox holds the same shared libraries as in the plain build); the
// grader's reports stay the same.

// The honest stub throws "not implemented yet" everywhere: it scores 0 on every test (checked
// below), which is what every hostile submission must score, test by test.
TEST(GraderHostile, TheHonestStubScoresZeroOnEveryTest) {
  const Results r = grade(kTool, "01", kExercises / "01-t2-plane", "--time-limit 1");
  ASSERT_EQ(r.tests.size(), 8u);
  for (const auto& t : r.tests) EXPECT_EQ(t.score, 0) << t.name;
}

// What a hidden test may say: how it ended, and nothing else.
bool plain_verdict(const std::string& s) {
  return s == "passed" || s == "failed" || s == "crashed" || s == "timed out" || s == "output limit" ||
         s.rfind("not run", 0) == 0;
}

// A file of the grader cache as it is: its content, or for a large one (a precompiled header,
// ~55 MB) its inode, size and times (a write, a truncation or a touch changes the change time).
std::string fingerprint(const fs::path& p) {
  struct stat st{};
  if (::lstat(p.c_str(), &st) != 0) return "gone";
  if (st.st_size < (1 << 20)) return slurp(p);
  return std::to_string(st.st_ino) + " " + std::to_string(st.st_size) + " " + std::to_string(st.st_mtim.tv_sec) + "." +
         std::to_string(st.st_mtim.tv_nsec) + " " + std::to_string(st.st_ctim.tv_sec) + "." + std::to_string(st.st_ctim.tv_nsec);
}

// Everything on the host a submission must leave alone.
struct HostState {
  std::set<std::string> files;               // under /usr/local, the top of /usr/bin and /
  std::map<std::string, std::string> cache;  // the grader cache, by fingerprint
  static HostState now() {
    HostState h;
    std::error_code ec;
    for (auto it = fs::recursive_directory_iterator("/usr/local", ec); it != fs::recursive_directory_iterator(); it.increment(ec))
      h.files.insert(it->path().string());
    for (const char* d : {"/usr/bin", "/"})
      for (const auto& e : fs::directory_iterator(d, ec)) h.files.insert(e.path().string());
    for (const auto& e : fs::directory_iterator(fs::path(T2_BINARY_DIR) / "grader-cache", ec))
      if (e.path().string().find(".tmp") == std::string::npos) h.cache[e.path().string()] = fingerprint(e.path());
    return h;
  }
};

// What a grading run whose sandbox user was `uid` left behind: its processes, files in /tmp,
// its cgroups (named after the grader's pid, which the uid encodes).
std::vector<std::string> leftovers(unsigned long uid) {
  std::vector<std::string> r;
  std::error_code ec;
  for (const char* d : {"/proc", "/tmp", "/var/tmp", "/dev/shm"})
    for (const auto& e : fs::directory_iterator(d, ec)) {
      struct stat st{};
      if (::lstat(e.path().c_str(), &st) == 0 && st.st_uid == uid) r.push_back(e.path().string());
    }
  const std::string cg = "t2grade-" + std::to_string(uid - 1900000000ul) + "-";
  for (const auto& c : fs::directory_iterator("/sys/fs/cgroup", ec))
    for (const auto& g : fs::directory_iterator(c.path(), ec))
      if (g.path().filename().string().rfind(cg, 0) == 0) r.push_back("cgroup " + g.path().string());
  return r;
}

unsigned long sandbox_uid_of(const Results& r) {
  const auto at = r.output.find("bubblewrap as uid ");
  return at == std::string::npos ? 0 : std::stoul(r.output.substr(at + 18));
}

// A hostile submission scores exactly what the honest stub scores, test by test; hidden tests
// say only how they ended; the host is left as it was.
void expect_like_stub(const fs::path& submission, Results& r, const std::string& extra = "") {
  const HostState before = HostState::now();
  r = grade(kTool, "01", submission, "--time-limit 1 " + extra);
  ASSERT_EQ(r.tests.size(), 8u);
  EXPECT_EQ(r.score, 0) << r.raw.substr(0, 3000);
  for (const auto& t : r.tests) {
    EXPECT_EQ(t.score, 0) << t.name << ": " << t.output;
    if (t.visibility != "visible") {
      EXPECT_TRUE(plain_verdict(t.output)) << t.name << ": " << t.output;
    }
  }
  const HostState after = HostState::now();
  std::vector<std::string> added;
  std::set_difference(after.files.begin(), after.files.end(), before.files.begin(), before.files.end(), std::back_inserter(added));
  EXPECT_TRUE(added.empty()) << "left on the host: " << added.front();
  for (const auto& [f, content] : before.cache) {
    const auto it = after.cache.find(f);
    EXPECT_TRUE(it != after.cache.end() && it->second == content) << "the grader cache changed: " << f;
  }
  const unsigned long uid = sandbox_uid_of(r);
  ASSERT_GE(uid, 1900000000ul) << r.output;
  for (int i = 0; i < 50 && !leftovers(uid).empty(); ++i) ::usleep(100000);
  const auto left = leftovers(uid);
  EXPECT_TRUE(left.empty()) << "still alive: " << left.front();
  EXPECT_FALSE(fs::exists("/t2-owned"));
}

std::vector<std::string> hostile_names() {
  std::vector<std::string> r;
  for (const auto& e : fs::directory_iterator(kHostile))
    if (e.is_directory()) r.push_back(e.path().filename().string());
  std::sort(r.begin(), r.end());
  return r;
}

class Hostile : public ::testing::TestWithParam<std::string> {};

// Every submission of exercises/_hostile/ (see its README): the attacks of issue 10 and before.
// The submissions that give right answers through the library: refused by name, not by result
// (issue 12: directly and behind macros; issue 29: t2::operator== instantiated on big
// integers, t2::antipode behind a template argument of 8192 characters, a t2::collinear whose
// name carries an ABI tag).
const std::map<std::string, std::vector<std::string>> kRefusedNaming = {
    {"forbidden-direct", {"t2::antipode", "t2::operator=="}},
    {"forbidden-macro", {"t2::antipode", "t2::operator=="}},
    {"operator-on-exact", {"t2::operator=="}},
    {"long-template-argument", {"t2::antipode"}},
    {"abi-tag", {"t2::collinear"}}};

// The submissions that reach code outside the exercise's allow-list (issue 29): they do not
// compile, and the compiler's message names what is not there.
const std::map<std::string, std::string> kRefusedCompiling = {
    {"boost-multiprecision", "boost/multiprecision/cpp_int.hpp: No such file or directory"},
    {"macro-before-include", "'lib_antipode' is not a member of 't2'"}};

// The submission that waits without using CPU time: only the wall-clock limit stops its tests,
// by default twice the CPU limit plus 2 s, 4 s a test. --wall-limit 1 stops them on the same
// path after 1 s (32 s of waiting a grading -> 8 s).
const std::set<std::string> kOnlyWaiting = {"sleeps"};

TEST_P(Hostile, ScoresWhatTheStubScoresAndLeavesNothing) {
  Results r;
  expect_like_stub(kHostile / GetParam(), r, kOnlyWaiting.count(GetParam()) ? "--wall-limit 1" : "");
  if (const auto it = kRefusedNaming.find(GetParam()); it != kRefusedNaming.end()) {
    EXPECT_NE(r.output.find("your code calls "), std::string::npos) << r.output;
    for (const auto& name : it->second) EXPECT_NE(r.output.find(name), std::string::npos) << name << ": " << r.output;
  }
  if (const auto it = kRefusedCompiling.find(GetParam()); it != kRefusedCompiling.end()) {
    std::string out = r.output;  // GCC quotes with ‘ ’ or ' ' depending on the locale
    for (const std::string q : {"\u2018", "\u2019"})
      for (size_t at; (at = out.find(q)) != std::string::npos;) out.replace(at, q.size(), "'");
    EXPECT_NE(out.find(it->second), std::string::npos) << r.output;
  }
}

INSTANTIATE_TEST_SUITE_P(All, Hostile, ::testing::ValuesIn(hostile_names()),
                         [](const ::testing::TestParamInfo<std::string>& i) {
                           std::string n = i.param;
                           for (auto& c : n)
                             if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
                           return n;
                         });

TEST(GraderHostile, AFifoInTheSubmissionIsRefusedWithoutWaiting) {
  TempDir t;
  fs::copy_file(kExercises / "01-t2-plane" / "solution" / "classify.cpp", t.path / "classify.cpp");
  ASSERT_EQ(::mkfifo((t.path / "notes").c_str(), 0644), 0);
  const auto start = std::chrono::steady_clock::now();
  const Results r = grade(kTool, "01", t.path);
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 60);
  EXPECT_EQ(r.score, 0);
  EXPECT_NE(r.output.find("notes is a FIFO"), std::string::npos) << r.output;
  // The source itself a FIFO: refused too, never opened for a blocking read.
  fs::remove(t.path / "notes");
  fs::remove(t.path / "classify.cpp");
  ASSERT_EQ(::mkfifo((t.path / "classify.cpp").c_str(), 0644), 0);
  EXPECT_EQ(grade(kTool, "01", t.path).score, 0);
}

TEST(GraderHostile, DoesNotCompile) {
  const Results r = grade(kTool, "01", kHostile / "does-not-compile");
  EXPECT_EQ(r.score, 0);
  for (const auto& t : r.tests) EXPECT_NE(t.output.find("does not compile"), std::string::npos) << t.output;
  EXPECT_NE(r.output.find("error"), std::string::npos) << "the compiler's message is shown: " << r.output;
  EXPECT_NE(r.output.find("classify.cpp:4"), std::string::npos) << r.output;
}

TEST(GraderHostile, ADemanglerBombEndsWithANamedVerdictWithinAMinute) {
  // A symbol of 650 bytes whose demangled form has 2^60 characters (issue 29, break 6): symbols
  // are read mangled, so the run ends, with the stub's verdicts.
  grade(kTool, "01", kExercises / "01-t2-plane", "--time-limit 1");  // warms the cache
  const auto start = std::chrono::steady_clock::now();
  const Results r = grade(kTool, "01", kHostile / "demangler-bomb", "--time-limit 1 --overall-limit 50");
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 60);
  EXPECT_EQ(r.score, 0);
  ASSERT_EQ(r.tests.size(), 8u);
  for (const auto& t : r.tests) EXPECT_EQ(t.output.find("not run"), std::string::npos) << t.name << ": " << t.output;
}

TEST(GraderHostile, AKilledRunLeavesNoTemporaryTree) {
  // `t2 grade` killed (SIGKILL to its whole process group) while it runs an endless submission:
  // its watcher, in a session of its own, removes /tmp/t2grade-* (here under a TMPDIR of the test's).
  TempDir t;
  fs::permissions(t.path, fs::perms::owner_all | fs::perms::group_exec | fs::perms::others_exec);
  grade(kTool, "01", kExercises / "01-t2-plane", "--time-limit 1");  // warms the cache
  auto trees = [&] {
    int n = 0;
    for (const auto& e : fs::directory_iterator(t.path))
      if (e.path().filename().string().rfind("t2grade-", 0) == 0) ++n;
    return n;
  };
  std::atomic<bool> seen{false}, done{false};
  std::thread watch([&] {
    while (!done) {
      if (trees() > 0) seen = true;
      ::usleep(20000);
    }
  });
  t2proc::Spec s;
  s.argv = {"/usr/bin/env", "TMPDIR=" + t.path.string(), kTool, "grade", "01", "--quiet", "--time-limit", "5",
            "--submission", (kHostile / "infinite-loop").string()};
  s.limits.wall_seconds = 6;
  const t2proc::Result r = t2proc::run(s);
  done = true;
  watch.join();
  EXPECT_TRUE(r.timed_out) << r.out << r.err;
  EXPECT_TRUE(seen) << "the run made its temporary tree under TMPDIR";
  for (int i = 0; i < 100 && trees() > 0; ++i) ::usleep(100000);
  EXPECT_EQ(trees(), 0) << "a killed run left its temporary tree";
}

TEST(GraderHostile, InfiniteLoopIsStoppedAndTheRunHasAnOverallLimit) {
  grade(kTool, "01", kExercises / "01-t2-plane");  // warms the cache: the overall limit counts builds too
  // Eleven tests of at least 1 s of CPU each cannot fit in 8 s: some must be cut by the limit, and
  // every test that ran must be reported as timed out (not as a crash: through bubblewrap the
  // CPU limit's signal arrives as an exit status).
  const auto start = std::chrono::steady_clock::now();
  const Results r = grade(kTool, "01", kHostile / "infinite-loop", "--time-limit 1 --overall-limit 8");
  const double took = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  EXPECT_LT(took, 30) << "the overall limit must stop the run";
  EXPECT_EQ(r.score, 0);
  int timed_out = 0, not_run = 0;
  for (const auto& t : r.tests) {
    EXPECT_EQ(t.score, 0) << t.name;
    if (t.output.find("timed out") != std::string::npos) ++timed_out;
    if (t.output.find("overall time limit") != std::string::npos) ++not_run;
  }
  EXPECT_EQ(timed_out + not_run, static_cast<int>(r.tests.size())) << r.output;
  EXPECT_GE(not_run, 1);
  EXPECT_NE(r.output.find("overall time limit"), std::string::npos) << r.output;
}

TEST(GraderHostile, CompilingHasItsOwnTimeLimit) {
  // A constant expression of billions of steps: the compiler is stopped at --compile-limit,
  // whatever the tests' limits, and the run says so.
  TempDir t;
  std::ofstream(t.path / "classify.cpp") << slurp(kExercises / "01-t2-plane" / "solution" / "classify.cpp") << R"(
constexpr long t2_slow() {  // 10^10 steps: each loop under GCC's loop limit, minutes to evaluate
  long s = 0;
  for (long i = 0; i < 100000; ++i)
    for (long j = 0; j < 100000; ++j) s += (i ^ j) % 7;
  return s;
}
static_assert(t2_slow() > 0);
)";
  grade(kTool, "01", kExercises / "01-t2-plane");  // warms the cache of trusted programs
  const auto start = std::chrono::steady_clock::now();
  const Results r = grade(kTool, "01", t.path, "--compile-limit 3");
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 30);
  EXPECT_EQ(r.score, 0);
  EXPECT_NE(r.output.find("ran out of time"), std::string::npos) << r.output;
  for (const auto& t : r.tests) EXPECT_NE(t.output.find("compiling ran out of time"), std::string::npos) << t.output;
}

TEST(GraderHostile, CrashesAreNamedOnPublicTestsOnly) {
  const Results r = grade(kTool, "01", kHostile / "segfault", "--time-limit 1");
  for (const auto& t : r.tests) {
    if (t.visibility == "visible") {
      EXPECT_NE(t.output.find("segmentation fault"), std::string::npos) << t.output;
    } else {
      EXPECT_EQ(t.output, "crashed");
    }
  }
}

TEST(GraderJudge, PrintingMegabytesCostsNothing) {
  TempDir t;
  std::ofstream(t.path / "classify.cpp") << slurp(kExercises / "01-t2-plane" / "solution" / "classify.cpp") << R"(
#include <cstdio>
#include <string>
static const int t2_noise = [] {
  const std::string kb(1023, 'x');
  for (int i = 0; i < 4096; ++i) { std::fprintf(stdout, "%s\n", kb.c_str()); std::fprintf(stderr, "%s\n", kb.c_str()); }
  return 0;
}();
)";
  const Results r = grade(kTool, "01", t.path);
  double max = 0;
  for (const auto& x : r.tests) max += x.max_score;
  EXPECT_EQ(r.score, max) << r.raw.substr(0, 2000);
  EXPECT_LT(r.raw.size(), 20000u) << "nothing of the output reaches the report";
}

TEST(GraderSandbox, TheProtectionLineIsWhatTheProbeFound) {
  const Results r = grade(kTool, "01", kExercises / "01-t2-plane" / "solution");
  const std::string& o = r.output;
  EXPECT_NE(o.find("bubblewrap as uid "), std::string::npos) << o;
  EXPECT_EQ(o.find("bubblewrap as uid 0 "), std::string::npos) << "student code must not run as root: " << o;
  for (const char* held : {"capabilities none", "seccomp filter", "/usr writable no", "remount no",
                           "new user namespace no", "network interfaces 0", "io_uring no", "netlink no",
                           "host paths in mountinfo 0", "hidden files unreadable 3/3"})
    EXPECT_NE(o.find(held), std::string::npos) << held << " in: " << o;
}

// Without root there is no cgroup for the submission's process tree: `t2 grade` refuses (exit
// 2, the reason named) unless --unsafe is given, and then grades with per-process limits and
// says so. The suite runs as root, so the test drops to uid 65534 with setpriv to see it.
TEST(GraderSandbox, WithoutRootItRefusesUnlessUnsafeAndSaysWhatIsNotBounded) {
  if (::geteuid() != 0) GTEST_SKIP() << "needs root to run the grader as another user";
  if (run("command -v setpriv").status != 0) GTEST_SKIP() << "setpriv (util-linux) is not installed";
  TempDir t;
  fs::permissions(t.path, fs::perms::all);  // the unprivileged grader writes its report and cache here
  const fs::path res = t.path / "results.json";
  const std::string as_nobody = "env HOME='" + t.path.string() + "' TMPDIR='" + t.path.string() +
                                "' setpriv --reuid=65534 --regid=65534 --clear-groups '" + kTool + "' grade 01 --quiet --submission '" +
                                (kExercises / "01-t2-plane" / "solution").string() + "' --results '" + res.string() + "'";
  const Ran refused = run(as_nobody);
  EXPECT_EQ(refused.status, 2) << refused.out;
  EXPECT_NE(refused.out.find("refusing to grade: no cgroup bounds the memory and CPU time"), std::string::npos) << refused.out;
  EXPECT_NE(refused.out.find("--unsafe"), std::string::npos) << refused.out;
  EXPECT_FALSE(fs::exists(res)) << "a refused grading writes no results";

  const Ran unsafe = run(as_nobody + " --unsafe");
  ASSERT_EQ(unsafe.status, 0) << unsafe.out;
  const auto j = nlohmann::json::parse(slurp(res));
  double max = 0;
  for (const auto& x : j.at("tests")) max += x.at("max_score").get<double>();
  EXPECT_GT(max, 0);
  EXPECT_EQ(j.at("score").get<double>(), max) << "the reference solution scores full marks without root too";
  const std::string out = j.at("output").get<std::string>();
  EXPECT_NE(out.find("bubblewrap as uid 65534"), std::string::npos) << out;
  EXPECT_NE(out.find("no cgroup (per-process limits only)"), std::string::npos) << out;
  EXPECT_NE(out.find("/dev writable no"), std::string::npos) << out;
}

TEST(GraderSandbox, CannotReadHiddenTestsNorWriteOutsideNorUseTheNetwork) {
  TempDir t, outside;
  const fs::path hidden = kExercises / "01-t2-plane" / "hidden" / "test_hidden.cpp";
  const fs::path target = outside.path / "escaped.txt";
  // At compile time: including the hidden tests by absolute path must fail.
  std::ofstream(t.path / "classify.cpp") << "#include \"" << hidden.string() << "\"\n";
  const Results c = grade(kTool, "01", t.path);
  EXPECT_EQ(c.score, 0);
  EXPECT_NE(c.output.find("not run"), std::string::npos) << c.output;
  // At run time: read the hidden tests and print them in a public test, write outside the
  // temporary directory, open a network connection.
  std::ofstream(t.path / "classify.cpp", std::ios::trunc) << R"(#include <arpa/inet.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>
#include <cstdio>
#include <stdexcept>
#include "classify.hpp"
namespace ex01 {
static void attempt() {
  if (FILE* h = std::fopen(")" << hidden.string() << R"(", "r")) {
    char buf[4096]; size_t n = std::fread(buf, 1, sizeof buf - 1, h); buf[n] = 0; throw std::runtime_error(buf);
  }
  if (FILE* f = std::fopen(")" << target.string() << R"(", "w")) { std::fputs("escaped\n", f); std::fclose(f); }
  int s = socket(AF_INET, SOCK_STREAM, 0);
  sockaddr_in a{}; a.sin_family = AF_INET; a.sin_port = htons(80);
  inet_pton(AF_INET, "127.0.0.1", &a.sin_addr);
  if (s >= 0 && connect(s, reinterpret_cast<sockaddr*>(&a), sizeof a) == 0) throw std::runtime_error("NETWORK-OK");
}
Where where(const t2::Point&) { attempt(); return Where::infinity; }
bool same_point(const t2::Point&, const t2::Point&) { attempt(); return false; }
bool antipodal(const t2::Point&, const t2::Point&) { attempt(); return false; }
}
)";
  const Results r = grade(kTool, "01", t.path);
  EXPECT_FALSE(fs::exists(target)) << "the submission wrote outside its temporary directory";
  EXPECT_EQ(r.raw.find("TEST(Hidden"), std::string::npos) << "the hidden tests were readable";
  EXPECT_EQ(r.raw.find("NETWORK-OK"), std::string::npos);
}

TEST(GraderReport, ResultsJsonHasGradescopesShape) {
  const Results r = grade(kTool, "03", kExercises / "03-predicates" / "wrong" / "seed-formula");
  double sum = 0;
  std::set<std::string> names;
  for (const auto& t : r.tests) {
    EXPECT_TRUE(names.insert(t.name).second) << "duplicate " << t.name;
    EXPECT_TRUE(t.visibility == "visible" || t.visibility == "hidden") << t.visibility;
    EXPECT_GE(t.score, 0);
    EXPECT_LE(t.score, t.max_score);
    sum += t.score;
  }
  EXPECT_EQ(r.score, sum);
  // Partial credit: the manifest's weights count.
  const Graded* w = r.find("Hidden.BothOnTheBackSide");
  ASSERT_NE(w, nullptr);
  EXPECT_EQ(w->max_score, 2);
  EXPECT_GT(r.score, 0);
  const Graded* f = r.find("Hidden.EqualPointsAtInfinity");
  ASSERT_NE(f, nullptr);
  EXPECT_EQ(f->score, 0) << "the seed's formula yields [0,0,0] there";
  EXPECT_NE(r.output.find("Protection: bubblewrap"), std::string::npos) << "the report says what protection is in force";
  // Hidden tests can be shown after the due date instead.
  const Results a = grade(kTool, "03", kExercises / "03-predicates" / "solution", "--hidden-visibility after_due_date");
  for (const auto& t : a.tests)
    EXPECT_EQ(t.visibility, t.name.rfind("Hidden.", 0) == 0 ? "after_due_date" : "visible") << t.name;
}

TEST(GraderCheck, PlainWordsHintsAndExitStatus) {
  const Ran bad = run("'" + kTool + "' check 01 --submission '" + (kExercises / "01-t2-plane" / "wrong" / "divide-by-w").string() + "'");
  EXPECT_EQ(bad.status, 1) << bad.out;
  EXPECT_NE(bad.out.find("FAILED  Public.AFrontPointAndItsAntipode"), std::string::npos) << bad.out;
  EXPECT_NE(bad.out.find("Hint"), std::string::npos) << "the test's hint is shown: " << bad.out;
  EXPECT_NE(bad.out.find("Next:"), std::string::npos) << bad.out;
  EXPECT_EQ(bad.out.find("Hidden."), std::string::npos) << "check runs only public tests: " << bad.out;
  const Ran good = run("'" + kTool + "' check 01 --submission '" + (kExercises / "01-t2-plane" / "solution").string() + "'");
  EXPECT_EQ(good.status, 0) << good.out;
  const Ran stub = run("'" + kTool + "' check 02");
  EXPECT_EQ(stub.status, 1);
  EXPECT_NE(stub.out.find("not implemented yet"), std::string::npos) << stub.out;
  const Ran none = run("'" + kTool + "' check 99");
  EXPECT_EQ(none.status, 2) << none.out;
}

}  // namespace
