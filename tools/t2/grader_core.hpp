#pragma once
// The grader shared by `t2 check`, `t2 grade` and `t2 release`: exercises and their manifests,
// and one run of an exercise's tests on a submission. The parts live a file each:
//   grader_exercise.cpp  manifests            grader_intake.cpp  copying the submission in
//   grader_sandbox.cpp   the sandbox          grader_build.cpp   trusted objects, sandboxed build
//   grader_elf.cpp       reading objects      grader_judge.cpp   driver and checker, verdicts
//   grader_report.cpp    results.json, summaries
// It does not depend on the command-line layer (command.hpp): its errors are GraderError.

#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "grader_sandbox.hpp"

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
  std::vector<std::string> forbidden;    ///< library names the submission must not refer to
  std::vector<std::string> allowed;      ///< library headers the submission may include ("t2/kernel/point.hpp");
                                         ///< its compile sees these, what they include, and the C++ standard library
  std::map<std::string, double> points;  ///< weight per test ("Suite.Name"); default 1
  double points_of(const std::string& test) const;  ///< weight of one test
  fs::path public_tests() const { return dir / "test_public.cpp"; }        ///< public tests
  fs::path hidden_tests() const { return dir / "hidden" / "test_hidden.cpp"; }  ///< hidden tests
  fs::path remote() const { return dir / "remote.cpp"; }                  ///< the API over the wire
  fs::path harness() const { return dir.parent_path() / "harness"; }      ///< driver/checker mains
  fs::path stub() const { return dir / source; }                          ///< the stub
  fs::path solution_dir() const { return dir / "solution"; }              ///< reference
};

/// The exercises folder: --exercises DIR, else $T2_EXERCISES_DIR, else the source tree's.
fs::path exercises_root(const std::optional<std::string>& override_dir);
/// Every exercise (folders named NN-slug holding exercise.txt), sorted.
std::vector<Exercise> all_exercises(const fs::path& root);
/// The exercise named by "NN", "NN-slug" or a path; throws GraderError when there is none.
Exercise find_exercise(const fs::path& root, const std::string& name);
/// Reads and checks a manifest; throws t2::BadInput naming the file and line.
Exercise read_exercise(const fs::path& dir);

/// The outcome of one test.
struct TestResult {
  std::string name;          ///< "Suite.Name"
  bool hidden = false;       ///< from the hidden tests
  bool passed = false;       ///< decided by the checker, a trusted process
  double max_score = 1;      ///< the weight
  std::string what;          ///< how it ended; for hidden tests only passed, failed, crashed,
                             ///< timed out or output limit
  std::string detail;        ///< failure messages of the test (public tests only)
};

/// The outcome of a whole run.
struct Report {
  Exercise exercise;
  bool compiled = false;
  std::string compiler_output;     ///< shortened compiler messages, or why the submission was refused
  std::vector<TestResult> tests;
  bool overall_timeout = false;    ///< the overall limit stopped the run
  std::string protection;          ///< what protected the machine, as probed
  double score() const;            ///< points earned
  double max_score() const;        ///< points possible
};

/// Options of a run.
struct RunOptions {
  bool include_hidden = false;     ///< grade (public + hidden) or check (public only)
  int overall_limit = 900;         ///< seconds for the whole run, builds included
  int compile_limit = 120;         ///< wall-clock seconds for compiling and linking the submission
  bool verbose = false;            ///< print progress to stderr
  int time_limit = 0;              ///< seconds of CPU per test; 0: the manifest's
  int wall_limit = 0;              ///< wall-clock seconds per test; 0: twice the CPU seconds plus 2
  bool unsafe = false;             ///< grade even where no cgroup bounds a run's whole process tree
};

/// Builds `submission_dir`/<source> in the sandbox and judges every test.
Report run_exercise(const Exercise& ex, const fs::path& submission_dir, const RunOptions& opt);

/// Gradescope's results.json for a report (hidden tests say only how they ended).
/// `hidden_visibility` is "hidden" or "after_due_date".
std::string results_json(const Report& r, const std::string& hidden_visibility = "hidden");
/// The human summary of `t2 grade`.
std::string grade_summary(const Report& r);
/// The plain-words report of `t2 check` (public tests, hints, what to try next).
std::string check_summary(const Report& r);

}  // namespace t2grader
