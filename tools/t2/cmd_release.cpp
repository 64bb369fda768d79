// `t2 release student|autograder|classroom OUT`: what instructors hand out.
#include <unistd.h>

#include <cstdlib>
#include <fstream>
#include <memory>
#include <optional>
#include <sstream>

#include <fmt/format.h>

#include "command.hpp"
#include "grader_core.hpp"
#include "grader_release.hpp"
#include "process.hpp"
#include <nlohmann/json.hpp>
#include "t2/kernel/io.hpp"

#ifndef T2_SOURCE_DIR
#define T2_SOURCE_DIR "."
#endif

namespace cmd_release {  // named: a unity build shares translation units

namespace fs = std::filesystem;

fs::path source_root() { return fs::path(T2_SOURCE_DIR); }

// Refuses a release in which any line of a reference solution, hidden test or wrong solution
// appears (by content, wherever it is), and removes what was written.
void check_no_leaks(const fs::path& out, const fs::path& cleanup) {
  const auto secrets = t2grader::secret_lines(source_root());
  const auto leaks = t2grader::find_leaks(out, secrets);
  if (leaks.empty()) return;
  std::error_code ec;
  fs::remove_all(cleanup, ec);
  std::string msg = "refusing the release: secret exercise content found in it:\n";
  for (const auto& l : leaks) msg += "  " + l + "\n";
  throw std::runtime_error(msg);
}

void write_release_note(const fs::path& out) {
  std::string s =
      "t2 student release\n\n"
      "Build once with ./build.sh, then work on an exercise:\n"
      "  edit exercises/NN-slug/<file>.cpp (the exercise's README.md says what to write)\n"
      "  build/default/bin/t2 check NN     # public tests, with hints\n\n"
      "Exercises:\n";
  for (const auto& e : t2grader::all_exercises(out / "exercises"))
    s += fmt::format("  {}  {}  (edit {})\n", e.id, e.title, e.source);
  t2::write_file_atomically(out / "EXERCISES.txt", s);
}

int student(const fs::path& out) {
  t2grader::copy_tree(source_root(), out, true);
  check_no_leaks(out, out);
  write_release_note(out);
  fmt::print("wrote the student release to {}\n", out.string());
  return t2cli::kOk;
}

int classroom(const fs::path& out) {
  t2grader::copy_tree(source_root(), out, true);
  check_no_leaks(out, out);
  write_release_note(out);
  nlohmann::ordered_json tests = nlohmann::ordered_json::array();
  for (const auto& e : t2grader::all_exercises(out / "exercises")) {
    const std::string id = e.id.substr(0, e.id.find('-'));
    // Classroom runs in the student's own repository: only the public tests exist there.
    tests.push_back({{"name", e.id + ": " + e.title}, {"setup", "./build.sh"}, {"run", "build/default/bin/t2 check " + id},
                     {"input", ""}, {"output", ""}, {"comparison", "included"}, {"timeout", 10}, {"points", 1}});
  }
  t2::write_file_atomically(out / ".github" / "classroom" / "autograding.json",
                            nlohmann::ordered_json{{"tests", tests}}.dump(2) + "\n");
  t2::write_file_atomically(out / ".github" / "workflows" / "classroom.yml",
                            "# GitHub Classroom autograding: the public tests of every exercise (t2 check).\n"
                            "# Hidden tests are graded by the instructor (t2 grade, or the Gradescope bundle).\n"
                            "name: Autograding\n"
                            "on: [push]\n"
                            "permissions:\n  checks: write\n  actions: read\n  contents: read\n"
                            "jobs:\n  autograding:\n    runs-on: ubuntu-latest\n    container: debian:12\n"
                            "    steps:\n      - uses: actions/checkout@v4\n"
                            "      - uses: education/autograding@v1\n");
  fmt::print("wrote the GitHub Classroom template repository to {} (.github/classroom/autograding.json)\n", out.string());
  return t2cli::kOk;
}

int autograder(const fs::path& zip, const std::optional<std::string>& exercise) {
  if (zip.extension() != ".zip") throw t2cli::UsageError("the autograder bundle must be a .zip file");
  // One bundle grades one exercise, named here: nothing in a submission chooses what it is graded as.
  if (!exercise)
    throw t2cli::UsageError("an autograder bundle grades one exercise: name it with --exercise NN "
                            "(one bundle per Gradescope assignment)");
  const std::string ex = t2grader::find_exercise(source_root() / "exercises", *exercise).id;
  std::string tmpl = (fs::temp_directory_path() / "t2release-XXXXXX").string();
  if (!mkdtemp(tmpl.data())) throw std::runtime_error("cannot create a temporary directory");
  const fs::path stage = fs::path(tmpl) / "bundle";
  struct Cleanup {
    fs::path p;
    ~Cleanup() {
      std::error_code ec;
      fs::remove_all(p, ec);
    }
  } cleanup{tmpl};
  t2grader::copy_tree(source_root(), stage, false);
  // Reference and wrong solutions and the worked answers are not needed to grade: leave them
  // out of the bundle too.
  for (const auto& e : t2grader::all_exercises(stage / "exercises")) {
    fs::remove_all(e.dir / "solution");
    fs::remove_all(e.dir / "wrong");
    fs::remove(e.dir / "answers.md");
  }
  fs::remove_all(stage / "exercises" / "_hostile");
  fs::remove_all(stage / "exercises" / "_template");
  t2::write_file_atomically(stage / "setup.sh",
      "#!/usr/bin/env bash\n"
      "# Gradescope autograder setup: build the t2 library and tool once.\n"
      "set -euo pipefail\n"
      "cd /autograder/source\n"
      "export DEBIAN_FRONTEND=noninteractive\n"
      "apt-get update -qq\n"
      "apt-get install -y -qq --no-install-recommends cmake g++ make pkg-config libgtest-dev libgmock-dev \\\n"
      "  libbenchmark-dev libfmt-dev libcairo2-dev libgmp-dev doxygen bubblewrap \\\n"
      "  libseccomp-dev nlohmann-json3-dev libcli11-dev util-linux\n"
      "cmake -S . -B build/default -DCMAKE_BUILD_TYPE=RelWithDebInfo\n"
      "cmake --build build/default -j2 --target t2_tool\n");
  t2::write_file_atomically(stage / "run_autograder",
      fmt::format("#!/usr/bin/env bash\n"
                  "# Gradescope entry point: grade /autograder/submission, write results.json.\n"
                  "cd /autograder/source\n"
                  "mkdir -p /autograder/results\n"
                  "build/default/bin/t2 grade {} --submission /autograder/submission \\\n"
                  "  --results /autograder/results/results.json --overall-limit 900\n",
                  ex));
  fs::permissions(stage / "setup.sh", fs::perms::owner_exec | fs::perms::group_exec | fs::perms::others_exec,
                  fs::perm_options::add);
  fs::permissions(stage / "run_autograder", fs::perms::owner_exec | fs::perms::group_exec | fs::perms::others_exec,
                  fs::perm_options::add);
  const fs::path tmpzip = fs::path(tmpl) / "bundle.zip";
  t2proc::Spec zip_run;
  zip_run.argv = {"zip", "-q", "-r", tmpzip.string(), "."};
  zip_run.cwd = stage;
  const t2proc::Result zipped = t2proc::run(zip_run);
  if (!zipped.ok())
    throw std::runtime_error("zip failed (is it installed? see scripts/deps.sh): " + zipped.error + zipped.err);
  std::ifstream in(tmpzip, std::ios::binary);
  std::ostringstream bytes;
  bytes << in.rdbuf();
  t2::write_file_atomically(zip, bytes.str());
  fmt::print("wrote the Gradescope autograder bundle {} (exercise: {})\n", zip.string(), ex);
  return t2cli::kOk;
}

struct Options {
  std::string kind, out;
  std::optional<std::string> exercise;
};

int release(const Options& o) {
  if (o.kind == "student") return student(o.out);
  if (o.kind == "classroom") return classroom(o.out);
  return autograder(o.out, o.exercise);
}

t2cli::Action setup(t2cli::Arguments& app) {
  auto o = std::make_shared<Options>();
  app.description(
      "student: the course for students (chapters, library, figures, exercise stubs and\n"
      "  public tests), without reference solutions, hidden tests or wrong solutions. It\n"
      "  builds with ./build.sh and has `t2 check`. The release is refused (and removed)\n"
      "  if any line of secret exercise content is found anywhere in it.\n"
      "autograder: a Gradescope bundle (setup.sh, run_autograder, the sources with the\n"
      "  hidden tests) that grades the exercise --exercise NN (required) with `t2 grade`,\n"
      "  the sandboxed judge.\n"
      "classroom: the student tree plus a GitHub Classroom autograding configuration\n"
      "  (.github/classroom/autograding.json) that runs the public tests.");
  app.add_option("KIND", o->kind, "student, autograder or classroom")
      ->required()
      ->check(t2cli::IsMember({"student", "autograder", "classroom"}));
  app.add_option("OUT", o->out, "the folder (or OUT.zip for autograder) to write")->required();
  app.add_option("--exercise", o->exercise, "autograder (required): the one exercise it grades")->type_name("NN");
  app.footer("Exit status: 0 written; 2 bad usage, an existing OUT, or secret content found.");
  return [o] { return release(*o); };
}

}  // namespace cmd_release

T2_COMMAND({"release", "write the student tree, a Gradescope autograder or a Classroom template", cmd_release::setup});
