// `t2 check NN`: the student's own run of the public tests, in plain words.
#include <fmt/format.h>

#include <optional>

#include "command.hpp"
#include "grader_core.hpp"

namespace {

int run(t2cli::Args args) {
  std::optional<std::string> name, submission, root;
  for (size_t i = 0; i < args.size(); ++i) {
    const std::string& a = args[i];
    auto value = [&] {
      if (i + 1 >= args.size()) throw t2cli::UsageError(a + " needs a value");
      return args[++i];
    };
    if (a == "--submission") submission = value();
    else if (a == "--exercises") root = value();
    else if (!a.empty() && a[0] == '-') throw t2cli::UsageError("unknown option " + a);
    else if (!name) name = a;
    else throw t2cli::UsageError("one exercise at a time");
  }
  if (!name) throw t2cli::UsageError("which exercise? e.g. t2 check 01");
  const auto ex = t2grader::find_exercise(t2grader::exercises_root(root), *name);
  t2grader::RunOptions opt;
  opt.include_hidden = false;
  const auto rep = t2grader::run_exercise(ex, submission ? t2grader::fs::path(*submission) : ex.dir, opt);
  fmt::print("{}", t2grader::check_summary(rep));
  return rep.compiled && rep.score() == rep.max_score() ? t2cli::kOk : t2cli::kFailed;
}

}  // namespace

T2_COMMAND({"check", "run the public tests of an exercise on your code, with hints",
            "Usage: t2 check NN [--submission DIR] [--exercises DIR]\n\n"
            "Builds your solution of exercise NN (the file named in its exercise.txt, by default\n"
            "the one in exercises/NN-slug/) with the exercise's public tests, runs each test in\n"
            "its own process with time and memory limits, and says in plain words what passed,\n"
            "what failed and why, with a hint for each failure. The hidden tests are not run.\n\n"
            "Exit status: 0 every public test passes, 1 something failed or does not compile.\n",
            run})
