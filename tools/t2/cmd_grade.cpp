// `t2 grade NN`: the instructor's (or Gradescope's) run of public and hidden tests.
#include <fmt/format.h>

#include <optional>

#include "command.hpp"
#include "grader_core.hpp"
#include "t2/io.hpp"

namespace {

// "auto": the exercise whose source file the submission holds (for one autograder bundle
// serving every exercise).
t2grader::Exercise pick(const t2grader::fs::path& root, const std::string& name,
                        const t2grader::fs::path& submission) {
  if (name != "auto") return t2grader::find_exercise(root, name);
  for (auto& e : t2grader::all_exercises(root))
    if (t2grader::fs::is_regular_file(submission / e.source)) return e;
  throw t2cli::UsageError("the submission holds no file of any exercise");
}

int run(t2cli::Args args) {
  std::optional<std::string> name, submission, results, root;
  bool quiet = false;
  std::string visibility = "hidden";
  int limit = 900, time_limit = 0;
  for (size_t i = 0; i < args.size(); ++i) {
    const std::string& a = args[i];
    auto value = [&] {
      if (i + 1 >= args.size()) throw t2cli::UsageError(a + " needs a value");
      return args[++i];
    };
    if (a == "--submission") submission = value();
    else if (a == "--results") results = value();
    else if (a == "--exercises") root = value();
    else if (a == "--quiet") quiet = true;
    else if (a == "--hidden-visibility") {
      visibility = value();
      if (visibility != "hidden" && visibility != "after_due_date")
        throw t2cli::UsageError("--hidden-visibility is hidden or after_due_date, not " + visibility);
    }
    else if (a == "--time-limit") {
      const std::string v = value();
      try {
        time_limit = std::stoi(v);
      } catch (const std::exception&) {
        throw t2cli::UsageError("--time-limit needs a number of seconds, not " + v);
      }
      if (time_limit <= 0) throw t2cli::UsageError("--time-limit must be positive");
    }
    else if (a == "--overall-limit") {
      const std::string v = value();
      try {
        limit = std::stoi(v);
      } catch (const std::exception&) {
        throw t2cli::UsageError("--overall-limit needs a number of seconds, not " + v);
      }
      if (limit <= 0) throw t2cli::UsageError("--overall-limit must be positive");
    } else if (!a.empty() && a[0] == '-') throw t2cli::UsageError("unknown option " + a);
    else if (!name) name = a;
    else throw t2cli::UsageError("one exercise at a time");
  }
  if (!name) throw t2cli::UsageError("which exercise? e.g. t2 grade 01 --submission DIR");
  const auto root_dir = t2grader::exercises_root(root);
  const t2grader::fs::path sub = submission ? t2grader::fs::path(*submission) : t2grader::fs::path(".");
  const auto ex = pick(root_dir, *name, sub);
  t2grader::RunOptions opt;
  opt.include_hidden = true;
  opt.overall_limit = limit;
  opt.time_limit = time_limit;
  const auto rep = t2grader::run_exercise(ex, sub, opt);
  if (results) t2::write_file_atomically(*results, t2grader::results_json(rep, visibility));
  if (!quiet) fmt::print("{}", t2grader::grade_summary(rep));
  return t2cli::kOk;
}

}  // namespace

T2_COMMAND({"grade", "grade a submission: public and hidden tests, Gradescope results.json",
            "Usage: t2 grade NN [--submission DIR] [--results FILE] [--overall-limit SECONDS]\n"
            "                   [--time-limit SECONDS] [--hidden-visibility hidden|after_due_date]\n"
            "                   [--exercises DIR] [--quiet]\n\n"
            "Builds the submission (DIR holds the exercise's source file; default: .) against the\n"
            "public and hidden tests of exercise NN (or `auto`: the exercise whose file DIR holds)\n"
            "and runs each test in its own sandboxed process with the manifest's time and memory\n"
            "limits (--time-limit overrides the CPU seconds per test). Pass or fail is decided\n"
            "from the test process itself (a per-run secret and\n"
            "its exit status), never from what it prints. A submission that does not compile\n"
            "scores 0. Writes Gradescope's results.json to FILE (hidden tests marked `hidden`, or\n"
            "`after_due_date`) and prints a summary.\n\n"
            "Exit status: 0 graded (whatever the score), 2 bad usage or a broken exercise.\n",
            run})
