#pragma once
// The grader shared by `t2 check`, `t2 grade` and `t2 release`: exercises and their manifests,
// building a submission against the prebuilt library, running each test in its own sandboxed,
// resource-limited process, and reporting (plain words and Gradescope's results.json).

#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace t2grader {

namespace fs = std::filesystem;

/// One exercise folder exercises/NN-slug/ and its manifest (exercise.txt).
struct Exercise {
  fs::path dir;               ///< exercises/NN-slug
  std::string id;             ///< "NN-slug"
  std::string title;          ///< manifest `title`
  std::string chapter;        ///< manifest `chapter`
  std::string header;         ///< the API header the student implements (in dir)
  std::string source;         ///< the file the student writes (stub in dir, reference in solution/)
  int time_limit = 10;        ///< seconds of CPU per test (wall clock: twice that plus 2)
  int memory_mb = 512;        ///< address-space limit per test
  std::map<std::string, double> points;  ///< weight per test ("Suite.Name"); default 1
  double points_of(const std::string& test) const;  ///< weight of one test
  fs::path public_tests() const { return dir / "test_public.cpp"; }        ///< public tests
  fs::path hidden_tests() const { return dir / "hidden" / "test_hidden.cpp"; }  ///< hidden tests
  fs::path stub() const { return dir / source; }                          ///< the stub
  fs::path solution_dir() const { return dir / "solution"; }              ///< reference
};

/// The exercises folder: --exercises DIR, else $T2_EXERCISES_DIR, else the source tree's.
fs::path exercises_root(const std::optional<std::string>& override_dir);
/// Every exercise (folders named NN-slug holding exercise.txt), sorted.
std::vector<Exercise> all_exercises(const fs::path& root);
/// The exercise named by "NN", "NN-slug" or a path; throws UsageError when there is none.
Exercise find_exercise(const fs::path& root, const std::string& name);
/// Reads and checks a manifest; throws t2::BadInput naming the file and line.
Exercise read_exercise(const fs::path& dir);

/// What protects the machine while student code runs.
struct Sandbox {
  bool bwrap = false;       ///< bubblewrap works here
  std::string description;  ///< one line, said plainly in every report
};
/// Probes bubblewrap once (T2_GRADER_NO_BWRAP=1 forces the rlimit-only mode).
const Sandbox& sandbox();

/// The outcome of one test.
struct TestResult {
  std::string name;          ///< "Suite.Name"
  bool hidden = false;       ///< from the hidden tests
  bool passed = false;       ///< decided from the per-run secret and the exit status only
  double max_score = 1;      ///< the weight
  std::string what;          ///< what happened, in plain words (crash, timeout, failed ...)
  std::string detail;        ///< failure messages of the test (public tests only)
};

/// The outcome of a whole run.
struct Report {
  Exercise exercise;
  bool compiled = false;
  std::string compiler_output;     ///< shortened compiler messages when it did not compile
  std::vector<TestResult> tests;
  bool overall_timeout = false;    ///< the overall limit stopped the run
  double score() const;            ///< points earned
  double max_score() const;        ///< points possible
};

/// Options of a run.
struct RunOptions {
  bool include_hidden = false;     ///< grade (public + hidden) or check (public only)
  int overall_limit = 900;         ///< seconds for the whole run, builds included
  bool verbose = false;            ///< print progress to stderr
  int time_limit = 0;              ///< seconds of CPU per test; 0: the manifest's
};

/// Builds `submission_dir`/<source> against the exercise's tests and runs every test.
Report run_exercise(const Exercise& ex, const fs::path& submission_dir, const RunOptions& opt);

/// Gradescope's results.json for a report (hidden tests say only what happened, never details).
/// `hidden_visibility` is "hidden" or "after_due_date".
std::string results_json(const Report& r, const std::string& hidden_visibility = "hidden");
/// The human summary of `t2 grade`.
std::string grade_summary(const Report& r);
/// The plain-words report of `t2 check` (public tests, hints, what to try next).
std::string check_summary(const Report& r);

/// JSON string literal with escapes.
std::string json_string(const std::string& s);

}  // namespace t2grader
