// Invariants of every graded exercise (issue 5), checked by running `t2 grade` for real:
// the reference solution scores full marks, the stub scores 0 on every hidden test, every
// hidden test fails on at least one of the wrong solutions kept under wrong/, the one that throws
// t2::Undefined for every input scores 0 on every test, and nothing of the
// hidden tests or reference solution shows up in what a student sees after grading.
#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <set>
#include <string>
#include <vector>

#include "../exercises/harness/grader_testing.hpp"

namespace {

namespace fs = std::filesystem;
using namespace t2::grader_testing;

const std::string kTool = T2_TOOL;
const fs::path kExercises = fs::path(T2_SOURCE_DIR) / "exercises";

std::vector<std::string> exercise_ids() {
  std::vector<std::string> r;
  std::error_code ec;
  for (const auto& e : fs::directory_iterator(kExercises, ec))
    if (e.is_directory() && fs::exists(e.path() / "exercise.txt") && e.path().filename().string()[0] != '_')
      r.push_back(e.path().filename().string());
  std::sort(r.begin(), r.end());
  return r;
}

bool sanitized() { return std::getenv("T2_SANITIZED") != nullptr; }

std::string trim(const std::string& s) {
  const auto b = s.find_first_not_of(" \t\r\n");
  if (b == std::string::npos) return {};
  return s.substr(b, s.find_last_not_of(" \t\r\n") - b + 1);
}

// Lines (≥ 30 characters) of the exercise's hidden tests, reference and wrong solutions that
// occur in none of its public files nor in the library headers: their appearance anywhere a
// student can look is a leak.
std::vector<std::string> secret_lines(const fs::path& dir) {
  std::string pub;
  for (const auto& e : fs::recursive_directory_iterator(fs::path(T2_SOURCE_DIR) / "lib" / "include"))
    if (e.is_regular_file()) pub += slurp(e.path());
  for (const auto& e : fs::directory_iterator(dir))
    if (e.is_regular_file()) pub += slurp(e.path());
  std::set<std::string> s;
  for (const char* sub : {"hidden", "solution", "wrong"}) {
    if (!fs::exists(dir / sub)) continue;
    for (const auto& e : fs::recursive_directory_iterator(dir / sub)) {
      if (!e.is_regular_file()) continue;
      std::istringstream in(slurp(e.path()));
      std::string l;
      while (std::getline(in, l)) {
        l = trim(l);
        if (l.size() >= 30) s.insert(l);
      }
    }
  }
  return absent_from(pub, {s.begin(), s.end()});
}

// Expects that the grading `r` shows none of `secrets`, and that a hidden test says only how it
// ended, never its assertions or data.
void expect_nothing_hidden_shown(const Results& r, const std::vector<std::string>& secrets, const std::string& what) {
  for (const auto& line : secrets) EXPECT_EQ(r.raw.find(line), std::string::npos) << what << " leaked: " << line;
  for (const auto& t : r.tests)
    if (t.visibility != "visible") {
      EXPECT_TRUE(t.output == "passed" || t.output.find('\n') == std::string::npos) << what << ": " << t.output;
      EXPECT_EQ(t.output.find("Expected"), std::string::npos) << what << ": " << t.output;
      EXPECT_EQ(t.output.find("Which is"), std::string::npos) << what << ": " << t.output;
    }
}

class Exercise : public ::testing::TestWithParam<std::string> {
 protected:
  void SetUp() override {
    if (sanitized()) GTEST_SKIP() << "grading compiles and runs many programs: skipped under sanitizers";
    dir = kExercises / GetParam();
  }
  fs::path dir;
};

TEST_P(Exercise, HasEverythingAnExerciseNeeds) {
  for (const char* f : {"README.md", "exercise.txt", "test_public.cpp", "hidden/test_hidden.cpp"})
    EXPECT_TRUE(fs::exists(dir / f)) << f;
  EXPECT_TRUE(fs::exists(dir / "solution")) << "reference solution";
  ASSERT_TRUE(fs::exists(dir / "wrong")) << "wrong solutions";
  EXPECT_GE(std::distance(fs::directory_iterator(dir / "wrong"), fs::directory_iterator{}), 1);
}

TEST_P(Exercise, ReferenceSolutionScoresFullMarks) {
  const Results r = grade(kTool, GetParam(), dir / "solution");
  double max = 0;
  int hidden = 0, visible = 0;
  for (const auto& t : r.tests) {
    max += t.max_score;
    EXPECT_EQ(t.score, t.max_score) << t.name << ": " << t.output;
    if (t.visibility == "visible") {
      ++visible;
      EXPECT_EQ(t.name.rfind("Public.", 0), 0u) << t.name;
    } else {
      ++hidden;
      EXPECT_TRUE(t.visibility == "hidden" || t.visibility == "after_due_date") << t.visibility;
      EXPECT_EQ(t.name.rfind("Hidden.", 0), 0u) << t.name;
    }
  }
  EXPECT_EQ(r.score, max);
  EXPECT_GE(visible, 1);
  EXPECT_GE(hidden, 1);
}

// The stub is graded once, for both what it scores and what it shows (the wrong solutions'
// gradings are checked the same way in EveryHiddenTestFailsOnSomeWrongSolution).
TEST_P(Exercise, StubScoresZeroAndShowsNothingHidden) {
  const auto secrets = secret_lines(dir);
  ASSERT_FALSE(secrets.empty());
  const Results r = grade(kTool, GetParam(), dir);
  for (const auto& t : r.tests) {
    if (t.visibility == "visible") continue;
    EXPECT_EQ(t.score, 0) << t.name;
  }
  EXPECT_EQ(r.score, 0) << "the stub throws 'not implemented yet' everywhere";
  expect_nothing_hidden_shown(r, secrets, "the stub");
}

// Each wrong solution is graded once, for both what its grading scores and what it shows
// (StubScoresZeroAndShowsNothingHidden checks the stub's grading the same way).
TEST_P(Exercise, EveryHiddenTestFailsOnSomeWrongSolution) {
  const auto secrets = secret_lines(dir);
  ASSERT_FALSE(secrets.empty());
  std::set<std::string> hidden, caught;
  for (const auto& w : fs::directory_iterator(dir / "wrong")) {
    const Results r = grade(kTool, GetParam(), w.path());
    expect_nothing_hidden_shown(r, secrets, w.path().filename().string());
    int failed_hidden = 0;
    for (const auto& t : r.tests) {
      if (t.visibility == "visible") continue;
      hidden.insert(t.name);
      if (t.score < t.max_score) {
        caught.insert(t.name);
        ++failed_hidden;
        EXPECT_EQ(t.output.find("compile"), std::string::npos)
            << w.path().filename() << " must compile: a wrong solution is wrong geometry, not a syntax error";
      }
    }
    EXPECT_GE(failed_hidden, 1) << w.path().filename() << " passes every hidden test: it is not wrong, or the tests are weak";
    if (w.path().filename() == "throws-undefined") {
      // Issue 29: every test that expects Undefined also checks an input where it is wrong.
      EXPECT_EQ(r.score, 0) << "throwing t2::Undefined for every input scores";
      for (const auto& t : r.tests) EXPECT_EQ(t.score, 0) << t.name << " passes when everything throws Undefined";
    }
  }
  EXPECT_TRUE(fs::exists(dir / "wrong" / "throws-undefined")) << "every exercise has the wrong solution that always throws Undefined";
  ASSERT_FALSE(hidden.empty());
  for (const auto& h : hidden) EXPECT_TRUE(caught.count(h)) << h << " fails on no wrong solution: it cannot fail";
}

INSTANTIATE_TEST_SUITE_P(All, Exercise, ::testing::ValuesIn(exercise_ids()),
                         [](const ::testing::TestParamInfo<std::string>& i) {
                           std::string n = "ex" + i.param;
                           for (auto& c : n)
                             if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
                           return n;
                         });

TEST(Exercises, TwoForEveryChapter) {
  // Folders NN-slug and NNb-slug, of rising difficulty (issue 12 for Part I, issue 13 onwards).
  const auto ids = exercise_ids();
  for (const char* want : {"01", "02", "03", "04", "05", "06", "07", "08", "09", "10", "11", "12", "13", "14", "15"}) {
    const auto n = std::count_if(ids.begin(), ids.end(), [&](const std::string& s) {
      return s.rfind(std::string(want) + "-", 0) == 0 || s.rfind(std::string(want) + "b-", 0) == 0;
    });
    EXPECT_GE(n, 2) << "chapter " << want << " needs at least two graded exercises";
  }
}

// The grader reads the compiled object's symbols: a solution of 14b that refers to the library's
// t2::locate_brute (declared by hand, since no allowed header declares it) scores 0, named.
TEST(Exercises, Ex14bRefusesTheLibrarysLocator) {
  if (sanitized()) GTEST_SKIP() << "grading compiles and runs programs: skipped under sanitizers";
  TempDir t;
  std::ofstream(t.path / "locate.cpp") << R"(#include "locate.hpp"
#include <stdexcept>
namespace t2 {
class Subdivision;
struct Location;
Location locate_brute(const Subdivision& S, const Point& p);
}  // namespace t2
namespace ex14b {
std::vector<Location> locate_all(const std::vector<t2::Point>&, const std::vector<Triangle>&,
                                 const std::vector<t2::Point>&) {
  using Brute = t2::Location (*)(const t2::Subdivision&, const t2::Point&);
  volatile Brute brute = &t2::locate_brute;
  (void)brute;
  throw std::logic_error("locate_all() is not implemented yet");
}
}  // namespace ex14b
)";
  const Results r = grade(kTool, "14b", t.path);
  EXPECT_EQ(r.score, 0);
  EXPECT_NE(r.output.find("your code calls t2::locate_brute"), std::string::npos) << r.output;
}

}  // namespace
