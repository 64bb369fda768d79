// The releases of the grader: nothing secret in the student tree, by content; an autograder
// bundle grades one fixed exercise; the Classroom template runs the public tests.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "../exercises/harness/grader_testing.hpp"

namespace {

namespace fs = std::filesystem;
using namespace t2::grader_testing;

const std::string kTool = T2_TOOL;
const fs::path kSource = T2_SOURCE_DIR;
const fs::path kExercises = kSource / "exercises";

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
    if (std::regex_search(s, std::regex("^exercises/[^/]+/((solution|hidden|wrong)/|answers\\.md$)")))
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
      if (l.size() >= 30) lines.insert(l);
    }
  }
  return absent_from(pub, {lines.begin(), lines.end()});
}

// The search both leak checks use (grader_testing.hpp) says what string::find says: lines at the
// start, in the middle and at the very end of the text, lines sharing their first window, absent.
TEST(Release, OccurInSaysWhatFindSays) {
  const std::string a(30, 'a'), text = a + "b" + "0123456789012345678901234567890123456789" + a + "cd" + a + "ef";
  const std::vector<std::string> lines = {a + "b", a + "c", a + "cd", a + "ef", a + "eg", a + "ef!",
                                          "0123456789012345678901234567890123456789", "1234567890123456789012345678901234567890a",
                                          text, text + "x"};
  const std::vector<bool> got = occur_in(text, lines);
  ASSERT_EQ(got.size(), lines.size());
  for (std::size_t i = 0; i < lines.size(); ++i) EXPECT_EQ(got[i], text.find(lines[i]) != std::string::npos) << lines[i];
  EXPECT_EQ(std::count(got.begin(), got.end(), true), 6);
}

TEST(Release, StudentTreeHoldsNothingSecret) {
  TempDir t;
  const fs::path out = t.path / "student";
  const Ran r = run("'" + kTool + "' release student '" + out.string() + "'");
  ASSERT_EQ(r.status, 0) << r.out;
  // What students need is there.
  for (const char* f : {"build.sh", "CMakeLists.txt", "lib/include/t2/t2.hpp", "tools/t2/cmd_check.cpp",
                        "exercises/harness/checker_main.cpp", "exercises/01-t2-plane/classify.cpp",
                        "exercises/01-t2-plane/test_public.cpp", "exercises/05-polygons/README.md"})
    EXPECT_TRUE(fs::exists(out / f)) << f;
  // The pen-and-paper questions are there, their worked answers are not.
  for (const char* ch : {"01-t2-plane", "02-primitives", "03-predicates", "04-robustness", "05-polygons"}) {
    ASSERT_TRUE(fs::exists(kExercises / ch / "answers.md")) << ch << ": the source tree has worked answers";
    EXPECT_NE(slurp(out / "exercises" / ch / "README.md").find("## Pen-and-paper questions"), std::string::npos) << ch;
    EXPECT_FALSE(fs::exists(out / "exercises" / ch / "answers.md")) << ch;
  }
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
    const std::vector<bool> leaked = occur_in(slurp(it->path()), secrets);
    for (std::size_t i = 0; i < secrets.size(); ++i) ASSERT_FALSE(leaked[i]) << it->path() << " leaks: " << secrets[i];
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

TEST(Release, AnAutograderBundleGradesOneExerciseTheSubmissionCannotChoose) {
  // Issue 29, break 5: a bundle that picked "the exercise whose file the submission holds" graded
  // a 10b submission holding a right classify.cpp as exercise 01. No such mode is left.
  TempDir t;
  const Ran r = run("'" + kTool + "' release autograder '" + (t.path / "all.zip").string() + "'");
  EXPECT_EQ(r.status, 2) << r.out;
  EXPECT_NE(r.out.find("--exercise"), std::string::npos) << r.out;
  EXPECT_FALSE(fs::exists(t.path / "all.zip"));
  const Ran g = run("'" + kTool + "' grade auto --quiet --submission '" + (kExercises / "01-t2-plane" / "solution").string() + "'");
  EXPECT_EQ(g.status, 2) << g.out;
}

TEST(Release, AutograderBundleAndClassroomConfig) {
  TempDir t;
  const fs::path zip = t.path / "autograder.zip";
  const Ran r = run("'" + kTool + "' release autograder '" + zip.string() + "' --exercise 01");
  ASSERT_EQ(r.status, 0) << r.out;
  const Ran l = run("unzip -l '" + zip.string() + "'");
  for (const char* f : {" setup.sh", " run_autograder", "exercises/01-t2-plane/hidden/test_hidden.cpp",
                        "exercises/harness/checker_main.cpp", "lib/include/t2/t2.hpp"})
    EXPECT_NE(l.out.find(f), std::string::npos) << f << "\n" << l.out;
  EXPECT_EQ(l.out.find("/solution/"), std::string::npos) << "reference solutions are not needed to grade";
  EXPECT_EQ(l.out.find("/wrong/"), std::string::npos);
  EXPECT_EQ(l.out.find("answers.md"), std::string::npos) << "worked answers stay with the instructor";
  const Ran ra = run("unzip -p '" + zip.string() + "' run_autograder");
  EXPECT_NE(ra.out.find("/autograder/results/results.json"), std::string::npos) << ra.out;
  EXPECT_NE(ra.out.find("t2 grade 01-t2-plane "), std::string::npos) << ra.out;

  const fs::path cls = t.path / "classroom";
  ASSERT_EQ(run("'" + kTool + "' release classroom '" + cls.string() + "'").status, 0);
  const auto j = nlohmann::json::parse(slurp(cls / ".github" / "classroom" / "autograding.json"));
  const auto& tests = j.at("tests");
  EXPECT_GE(tests.size(), 5u);
  for (const auto& x : tests) {
    EXPECT_NE(x.at("run").get<std::string>().find("t2 check"), std::string::npos);
    for (const char* k : {"name", "setup", "run", "comparison", "timeout", "points"}) EXPECT_TRUE(x.contains(k)) << k;
  }
  EXPECT_FALSE(fs::exists(cls / "exercises" / "01-t2-plane" / "hidden"));
}

// The three gradings run one judge: `t2 grade` (what the instructor runs, and what these tests
// run through grader_testing.hpp), the Gradescope bundle's run_autograder, and the Classroom
// template's autograding command (t2 check, public tests). Each is run as released, on its own
// copy of the exercise (T2_EXERCISES_DIR: the bundle's and the template's), with this build's
// tool where the release would have built its own; all three give the same verdict on every test.
TEST(Release, TheThreeGradingsRunOneJudge) {
  TempDir t;
  const fs::path sub = kExercises / "01-t2-plane" / "wrong" / "divide-by-w";  // some tests pass, some fail
  const Results local = grade(kTool, "01", sub);
  ASSERT_GT(local.score, 0);

  // Gradescope: the bundle unpacked where run_autograder expects it (/autograder moved into t).
  const fs::path ag = t.path / "autograder", zip = t.path / "bundle.zip";
  ASSERT_EQ(run("'" + kTool + "' release autograder '" + zip.string() + "' --exercise 01").status, 0);
  fs::create_directories(ag / "source");
  ASSERT_EQ(run("cd '" + (ag / "source").string() + "' && unzip -q '" + zip.string() + "'").status, 0);
  fs::create_directories(ag / "source" / "build" / "default" / "bin");
  fs::create_symlink(kTool, ag / "source" / "build" / "default" / "bin" / "t2");
  fs::create_directories(ag / "submission");
  fs::copy_file(sub / "classify.cpp", ag / "submission" / "classify.cpp");
  std::string script = slurp(ag / "source" / "run_autograder");
  for (size_t at = 0; (at = script.find("/autograder/", at)) != std::string::npos; at += ag.string().size() + 1)
    script.replace(at, 12, ag.string() + "/");
  std::ofstream(ag / "run.sh") << script;
  const Ran g = run("T2_EXERCISES_DIR='" + (ag / "source" / "exercises").string() + "' bash '" + (ag / "run.sh").string() + "'");
  ASSERT_EQ(g.status, 0) << g.out;
  const auto bundle = nlohmann::json::parse(slurp(ag / "results" / "results.json"));
  EXPECT_EQ(bundle.at("score").get<double>(), local.score);
  ASSERT_EQ(bundle.at("tests").size(), local.tests.size());
  for (size_t i = 0; i < local.tests.size(); ++i) {
    const auto& b = bundle.at("tests")[i];
    EXPECT_EQ(b.at("name").get<std::string>(), local.tests[i].name);
    EXPECT_EQ(b.at("score").get<double>(), local.tests[i].score) << local.tests[i].name;
    EXPECT_EQ(b.at("output").get<std::string>(), local.tests[i].output) << local.tests[i].name;
  }

  // Classroom: the template's own command, in the template, with the submission in place.
  const fs::path cls = t.path / "classroom";
  ASSERT_EQ(run("'" + kTool + "' release classroom '" + cls.string() + "'").status, 0);
  fs::copy_file(sub / "classify.cpp", cls / "exercises" / "01-t2-plane" / "classify.cpp", fs::copy_options::overwrite_existing);
  fs::create_directories(cls / "build" / "default" / "bin");
  fs::create_symlink(kTool, cls / "build" / "default" / "bin" / "t2");
  std::string command;
  const auto config = nlohmann::json::parse(slurp(cls / ".github" / "classroom" / "autograding.json"));
  for (const auto& x : config.at("tests"))
    if (x.at("name").get<std::string>().rfind("01-t2-plane:", 0) == 0) command = x.at("run").get<std::string>();
  ASSERT_FALSE(command.empty());
  const Ran c = run("cd '" + cls.string() + "' && T2_EXERCISES_DIR='" + (cls / "exercises").string() + "' " + command);
  int public_tests = 0;
  for (const auto& l : local.tests) {
    if (l.visibility != "visible") continue;
    ++public_tests;
    const bool passed = l.score == l.max_score;
    EXPECT_NE(c.out.find((passed ? "  passed  " : "  FAILED  ") + l.name), std::string::npos) << l.name << "\n" << c.out;
  }
  EXPECT_GE(public_tests, 1);
}

}  // namespace
