// `t2 grade NN`: the instructor's (or Gradescope's) run of public and hidden tests.
#include <fmt/format.h>

#include <memory>
#include <optional>

#include "command.hpp"
#include "grader_core.hpp"
#include "t2/kernel/io.hpp"

namespace t2cli {
namespace cmd_grade {

namespace fs = std::filesystem;

struct Options {
  std::string name;
  std::string submission = ".";
  std::optional<std::string> results, root;
  int overall_limit = 900, compile_limit = 120, time_limit = 0, wall_limit = 0;
  std::string visibility = "hidden";
  bool quiet = false, unsafe = false;
};

int grade(const Options& o) {
  const fs::path sub = o.submission;
  const auto ex = t2grader::find_exercise(t2grader::exercises_root(o.root), o.name);
  t2grader::RunOptions opt;
  opt.include_hidden = true;
  opt.overall_limit = o.overall_limit;
  opt.compile_limit = o.compile_limit;
  opt.time_limit = o.time_limit;
  opt.wall_limit = o.wall_limit;
  opt.unsafe = o.unsafe;
  const auto rep = t2grader::run_exercise(ex, sub, opt);
  if (o.results) t2::write_file_atomically(*o.results, t2grader::results_json(rep, o.visibility));
  if (!o.quiet) fmt::print("{}", t2grader::grade_summary(rep));
  return kOk;
}

Action setup(Arguments& app) {
  auto o = std::make_shared<Options>();
  app.description(
      "Builds the submission (DIR holds the exercise's source file; default: .) in the sandbox\n"
      "and judges it with the public and hidden tests of exercise NN (always named: nothing in\n"
      "the submission chooses the exercise). Each test runs the submission's functions in a sandboxed driver\n"
      "process, with the manifest's time and memory limits; the tests and their oracles run in\n"
      "another process that never links student code and compares the answers, so nothing the\n"
      "submission prints or defines decides a verdict. A submission that does not compile, or\n"
      "calls a forbidden library function, scores 0. Writes Gradescope's results.json to FILE\n"
      "(hidden tests marked `hidden`, or `after_due_date`) and prints a summary.");
  app.add_option("NN", o->name, "the exercise: NN, NN-slug or a path")->required();
  app.add_option("--submission", o->submission, "the submission folder (default: .)")->type_name("DIR");
  app.add_option("--results", o->results, "write Gradescope's results.json here")->type_name("FILE");
  app.add_option("--overall-limit", o->overall_limit, "seconds for the whole run (default 900)")
      ->type_name("SECONDS")
      ->check(PositiveNumber);
  app.add_option("--compile-limit", o->compile_limit, "seconds for compiling and linking (default 120)")
      ->type_name("SECONDS")
      ->check(PositiveNumber);
  app.add_option("--time-limit", o->time_limit, "CPU seconds per test (default: the manifest's)")
      ->type_name("SECONDS")
      ->check(PositiveNumber);
  app.add_option("--wall-limit", o->wall_limit,
                 "wall-clock seconds per test (default: twice the CPU seconds plus 2; the grader's\n"
                 "own tests shorten it for submissions that only wait)")
      ->type_name("SECONDS")
      ->check(PositiveNumber);
  app.add_option("--hidden-visibility", o->visibility, "hidden or after_due_date")
      ->check(IsMember({"hidden", "after_due_date"}));
  app.add_option("--exercises", o->root, "the exercises folder")->type_name("DIR");
  app.add_flag("--quiet", o->quiet, "print no summary");
  app.add_flag("--unsafe", o->unsafe,
               "grade even without root, where no cgroup bounds the memory and CPU time of the\n"
               "submission's whole process tree (per-process limits only)");
  app.footer("Exit status: 0 graded (whatever the score), 2 bad usage or a broken exercise.");
  return [o] { return grade(*o); };
}

}  // namespace cmd_grade

T2_COMMAND({"grade", "grade a submission: public and hidden tests, Gradescope results.json", cmd_grade::setup});

}  // namespace t2cli
