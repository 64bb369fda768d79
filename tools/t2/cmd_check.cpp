// `t2 check NN`: the student's own run of the public tests, in plain words.
#include <fmt/format.h>

#include <memory>
#include <optional>

#include "command.hpp"
#include "grader_core.hpp"

namespace t2cli {
namespace cmd_check {

struct Options {
  std::string name;
  std::optional<std::string> submission, root;
};

int check(const Options& o) {
  const auto ex = t2grader::find_exercise(t2grader::exercises_root(o.root), o.name);
  t2grader::RunOptions opt;
  opt.include_hidden = false;
  const auto rep = t2grader::run_exercise(ex, o.submission ? t2grader::fs::path(*o.submission) : ex.dir, opt);
  fmt::print("{}", t2grader::check_summary(rep));
  return rep.compiled && rep.score() == rep.max_score() ? kOk : kFailed;
}

Action setup(Arguments& app) {
  auto o = std::make_shared<Options>();
  app.description(
      "Builds your solution of exercise NN (the file named in its exercise.txt, by default\n"
      "the one in exercises/NN-slug/) in the sandbox, runs the exercise's public tests on it,\n"
      "each in its own process with time and memory limits, and says in plain words what\n"
      "passed, what failed and why, with a hint for each failure. The hidden tests are not run.");
  app.add_option("NN", o->name, "the exercise: NN, NN-slug or a path")->required();
  app.add_option("--submission", o->submission, "the folder holding your file")->type_name("DIR");
  app.add_option("--exercises", o->root, "the exercises folder")->type_name("DIR");
  app.footer("Exit status: 0 every public test passes, 1 something failed or does not compile.");
  return [o] { return check(*o); };
}

}  // namespace cmd_check

T2_COMMAND({"check", "run the public tests of an exercise on your code, with hints", cmd_check::setup});

}  // namespace t2cli
