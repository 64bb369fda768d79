// The grader against hostile submissions, its reports (results.json, t2 check), its sandbox,
// and the releases (nothing secret in the student tree, by content).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <regex>
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
// programs it builds (libt2.a needs the sanitizer runtime); the grader's reports stay the same.

bool bwrap_in_force() {
  const Ran r = run("'" + kTool + "' grade 01 --submission '" + (kExercises / "01-t2-plane").string() + "'");
  return r.out.find("protection: bubblewrap") != std::string::npos;
}

// Every test of a hostile submission scores 0 and says what happened.
void expect_all_zero(const Results& r, const std::string& words) {
  ASSERT_FALSE(r.tests.empty());
  EXPECT_EQ(r.score, 0);
  for (const auto& t : r.tests) {
    EXPECT_EQ(t.score, 0) << t.name;
    EXPECT_NE(t.output.find(words), std::string::npos) << t.name << ": " << t.output;
  }
}

TEST(GraderHostile, DoesNotCompile) {
  const Results r = grade(kTool, "01", kHostile / "does-not-compile");
  expect_all_zero(r, "does not compile");
  EXPECT_NE(r.output.find("error"), std::string::npos) << "the compiler's message is shown: " << r.output;
  EXPECT_NE(r.output.find("classify.cpp:4"), std::string::npos) << r.output;
}

TEST(GraderHostile, InfiniteLoopIsStoppedAndTheRunHasAnOverallLimit) {
  // Warm the cache of compiled tests first: the overall limit counts builds too.
  grade(kTool, "01", kExercises / "01-t2-plane");
  // Eight tests of at least 1 s of CPU each cannot fit in 8 s: some must be cut by the limit.
  const auto start = std::chrono::steady_clock::now();
  const Results r = grade(kTool, "01", kHostile / "infinite-loop", "--time-limit 1 --overall-limit 8");
  const double took = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  EXPECT_LT(took, 30) << "the overall limit must stop the run";
  EXPECT_EQ(r.score, 0);
  int cpu = 0, not_run = 0;
  for (const auto& t : r.tests) {
    EXPECT_EQ(t.score, 0) << t.name;
    if (t.output.find("CPU time") != std::string::npos || t.output.find("timed out") != std::string::npos) ++cpu;
    if (t.output.find("overall time limit") != std::string::npos) ++not_run;
  }
  EXPECT_GE(cpu, 1);
  EXPECT_GE(not_run, 1);
  EXPECT_NE(r.output.find("overall time limit"), std::string::npos) << r.output;
}

TEST(GraderHostile, SleepingIsStoppedByTheWallClock) {
  grade(kTool, "01", kExercises / "01-t2-plane");  // warm the cache of compiled tests
  const Results r = grade(kTool, "01", kHostile / "sleeps", "--time-limit 1 --overall-limit 9");
  EXPECT_EQ(r.score, 0);
  int timed_out = 0;
  for (const auto& t : r.tests) {
    EXPECT_EQ(t.score, 0) << t.name;
    if (t.output.find("timed out") != std::string::npos) ++timed_out;
  }
  EXPECT_GE(timed_out, 1) << "a test that never returns is a timeout, never a pass";
}

TEST(GraderHostile, Segfault) {
  expect_all_zero(grade(kTool, "01", kHostile / "segfault"), "segmentation fault");
}

TEST(GraderHostile, StackOverflow) {
  expect_all_zero(grade(kTool, "01", kHostile / "stack-overflow"), "SIGSEGV");
}

TEST(GraderHostile, HugeAllocation) {
  expect_all_zero(grade(kTool, "01", kHostile / "huge-allocation"), "memory");
}

TEST(GraderHostile, HugeOutput) {
  const Results r = grade(kTool, "01", kHostile / "huge-output");
  expect_all_zero(r, "output");
  EXPECT_LT(r.raw.size(), 100000u) << "the output is capped";
}

TEST(GraderHostile, ExitZeroInTheMiddle) {
  expect_all_zero(grade(kTool, "01", kHostile / "exit-zero"), "exit");
}

TEST(GraderHostile, FakeTestOutputGainsNothing) {
  expect_all_zero(grade(kTool, "01", kHostile / "fake-output"), "before the test finished");
}

TEST(GraderHostile, ForgedRecordWithoutExitGainsNothing) {
  // Wrong answers, fake gtest text and a forged record, then an ordinary return.
  TempDir t;
  std::ofstream(t.path / "classify.cpp") << R"(#include <unistd.h>
#include <cstdio>
#include "classify.hpp"
namespace ex01 {
static void forge() {
  std::printf("[  PASSED  ] 1 test.\n");
  for (int fd = 3; fd < 10; ++fd) { ssize_t n = write(fd, "0123456789abcdef0123456789abcdef\nPASS\n", 38); (void)n; }
}
Where where(const t2::Point&) { forge(); return Where::infinity; }
bool same_point(const t2::Point&, const t2::Point&) { forge(); return false; }
bool antipodal(const t2::Point&, const t2::Point&) { forge(); return true; }
}
)";
  const Results r = grade(kTool, "01", t.path);
  EXPECT_EQ(r.score, 0);
}

TEST(GraderSandbox, CannotReadHiddenTestsNorWriteOutsideNorUseTheNetwork) {
  if (!bwrap_in_force()) GTEST_SKIP() << "bubblewrap does not work here: the grader runs with rlimits only";
  TempDir t, outside;
  const fs::path hidden = kExercises / "01-t2-plane" / "hidden" / "test_hidden.cpp";
  const fs::path target = outside.path / "escaped.txt";
  // At compile time: including the hidden tests by absolute path must fail.
  std::ofstream(t.path / "classify.cpp") << "#include \"" << hidden.string() << "\"\n";
  const Results c = grade(kTool, "01", t.path);
  EXPECT_EQ(c.score, 0);
  EXPECT_NE(c.output.find("does not compile"), std::string::npos) << c.output;
  // At run time: read the hidden tests and print them in a public test, write outside the
  // temporary directory, open a network connection.
  std::ofstream(t.path / "classify.cpp", std::ios::trunc) << R"(#include <arpa/inet.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>
#include <cstdio>
#include "classify.hpp"
namespace ex01 {
static void attempt() {
  if (FILE* h = std::fopen(")" << hidden.string() << R"(", "r")) {
    char buf[4096]; size_t n = std::fread(buf, 1, sizeof buf - 1, h); buf[n] = 0; std::printf("%s", buf); std::fclose(h);
  }
  if (FILE* f = std::fopen(")" << target.string() << R"(", "w")) { std::fputs("escaped\n", f); std::fclose(f); }
  int s = socket(AF_INET, SOCK_STREAM, 0);
  sockaddr_in a{}; a.sin_family = AF_INET; a.sin_port = htons(80);
  inet_pton(AF_INET, "127.0.0.1", &a.sin_addr);
  if (s >= 0 && connect(s, reinterpret_cast<sockaddr*>(&a), sizeof a) == 0) std::puts("NETWORK-OK");
  if (s >= 0) std::printf("socket=%d\n", s);
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
  EXPECT_NE(r.output.find("Protection:"), std::string::npos) << "the report says what protection is in force";
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

// ---- releases ---------------------------------------------------------------------------

std::string trim(const std::string& s) {
  const auto b = s.find_first_not_of(" \t\r\n");
  if (b == std::string::npos) return {};
  return s.substr(b, s.find_last_not_of(" \t\r\n") - b + 1);
}

// Lines of every secret file that occur in no released (public) file of the source tree.
std::vector<std::string> all_secret_lines() {
  std::string pub;
  std::vector<fs::path> secret_files;
  for (auto it = fs::recursive_directory_iterator(kSource, fs::directory_options::follow_directory_symlink); it != fs::recursive_directory_iterator(); ++it) {
    const auto rel = it->path().lexically_relative(kSource);
    const std::string top = rel.begin()->string();
    if (top == ".git" || (top.rfind("build", 0) == 0 && top != "build.sh")) {
      it.disable_recursion_pending();
      continue;
    }
    if (!it->is_regular_file()) continue;
    const std::string s = rel.string();
    if (std::regex_search(s, std::regex("^exercises/[^/]+/(solution|hidden|wrong)/")))
      secret_files.push_back(it->path());
    else if (s.rfind("exercises/_", 0) != 0 && s.rfind("tests/test_grader", 0) != 0 && s.rfind("tests/test_exercises", 0) != 0)
      pub += slurp(it->path());
  }
  std::set<std::string> lines;
  for (const auto& f : secret_files) {
    std::istringstream in(slurp(f));
    std::string l;
    while (std::getline(in, l)) {
      l = trim(l);
      if (l.size() >= 30 && pub.find(l) == std::string::npos) lines.insert(l);
    }
  }
  return {lines.begin(), lines.end()};
}

TEST(Release, StudentTreeHoldsNothingSecret) {
  TempDir t;
  const fs::path out = t.path / "student";
  const Ran r = run("'" + kTool + "' release student '" + out.string() + "'");
  ASSERT_EQ(r.status, 0) << r.out;
  // What students need is there.
  for (const char* f : {"build.sh", "CMakeLists.txt", "lib/include/t2/t2.hpp", "tools/t2/cmd_check.cpp",
                        "exercises/harness/harness_main.cpp", "exercises/01-t2-plane/classify.cpp",
                        "exercises/01-t2-plane/test_public.cpp", "exercises/05-polygons/README.md"})
    EXPECT_TRUE(fs::exists(out / f)) << f;
  // Nothing secret, by name ...
  for (auto it = fs::recursive_directory_iterator(out); it != fs::recursive_directory_iterator(); ++it) {
    const std::string s = it->path().lexically_relative(out).string();
    EXPECT_FALSE(std::regex_search(s, std::regex("(^|/)(solution|hidden|wrong|_hostile|\\.git)(/|$)"))) << s;
    EXPECT_EQ(s.rfind("tests/test_grader", 0), std::string::npos) << s;
  }
  // ... and by content, anywhere.
  const auto secrets = all_secret_lines();
  ASSERT_GT(secrets.size(), 50u);
  for (auto it = fs::recursive_directory_iterator(out); it != fs::recursive_directory_iterator(); ++it) {
    if (!it->is_regular_file()) continue;
    const std::string text = slurp(it->path());
    for (const auto& l : secrets) ASSERT_EQ(text.find(l), std::string::npos) << it->path() << " leaks: " << l;
  }
  // A second release into the same non-empty folder is refused.
  EXPECT_EQ(run("'" + kTool + "' release student '" + out.string() + "'").status, 2);
}

TEST(Release, CheckWorksWithTheStudentExercisesOnly) {
  TempDir t;
  const fs::path out = t.path / "student";
  ASSERT_EQ(run("'" + kTool + "' release student '" + out.string() + "'").status, 0);
  const Ran c = run("'" + kTool + "' check 04 --exercises '" + (out / "exercises").string() + "' --submission '" +
                    (kExercises / "04-robustness" / "solution").string() + "'");
  EXPECT_EQ(c.status, 0) << c.out;
  EXPECT_NE(c.out.find("2 of 2 public tests pass"), std::string::npos) << c.out;
}

TEST(Release, AutograderBundleAndClassroomConfig) {
  TempDir t;
  const fs::path zip = t.path / "autograder.zip";
  const Ran r = run("'" + kTool + "' release autograder '" + zip.string() + "'");
  ASSERT_EQ(r.status, 0) << r.out;
  const Ran l = run("unzip -l '" + zip.string() + "'");
  for (const char* f : {" setup.sh", " run_autograder", "exercises/01-t2-plane/hidden/test_hidden.cpp",
                        "exercises/harness/harness_main.cpp", "lib/include/t2/t2.hpp"})
    EXPECT_NE(l.out.find(f), std::string::npos) << f << "\n" << l.out;
  EXPECT_EQ(l.out.find("/solution/"), std::string::npos) << "reference solutions are not needed to grade";
  EXPECT_EQ(l.out.find("/wrong/"), std::string::npos);
  const Ran ra = run("unzip -p '" + zip.string() + "' run_autograder");
  EXPECT_NE(ra.out.find("/autograder/results/results.json"), std::string::npos) << ra.out;

  const fs::path cls = t.path / "classroom";
  ASSERT_EQ(run("'" + kTool + "' release classroom '" + cls.string() + "'").status, 0);
  const Json j = JsonParser(slurp(cls / ".github" / "classroom" / "autograding.json")).parse();
  const auto& tests = j["tests"].array();
  EXPECT_GE(tests.size(), 5u);
  for (const auto& x : tests) {
    EXPECT_NE(x["run"].str().find("t2 check"), std::string::npos);
    for (const char* k : {"name", "setup", "run", "comparison", "timeout", "points"}) EXPECT_TRUE(x.has(k)) << k;
  }
  EXPECT_FALSE(fs::exists(cls / "exercises" / "01-t2-plane" / "hidden"));
}

}  // namespace
