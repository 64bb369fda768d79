// t2 run NN: build the program of a chapter if needed, then run it.
#include <fmt/format.h>

#include <memory>
#include <string>
#include <vector>

#include "book_core.hpp"
#include "command.hpp"

namespace t2cli {
namespace cmd_run {

namespace fs = std::filesystem;

struct Options {
  std::string chapter;
  bool no_build = false;
};

int run(const Options& o, const std::vector<std::string>& args) {
  const auto c = book::find_chapter(book::default_root(), o.chapter);
  if (!c) throw UsageError("no chapter '" + o.chapter + "' (t2 list shows them)");
  if (!c->has_program) throw UsageError("chapter " + c->folder() + " has no program (main.cpp) yet");
  const fs::path build = book::own_build_dir();
  const std::string target = "chapter_" + c->number;
  if (!o.no_build) {
    // cmake's progress goes to stderr, so that stdout holds only the program's output.
    const int rc = book::run_program({"cmake", "--build", build.string(), "--target", target}, true);
    if (rc != 0) {
      fmt::print(stderr, "t2 run: building {} in {} failed\n", target, build.string());
      return kFailed;
    }
  }
  const fs::path exe = build / "bin" / target;
  if (!fs::exists(exe)) {
    fmt::print(stderr, "t2 run: {} does not exist (build the target {})\n", exe.string(), target);
    return kFailed;
  }
  std::vector<std::string> argv = {exe.string()};
  argv.insert(argv.end(), args.begin(), args.end());
  const int rc = book::run_program(argv);
  return rc < 0 ? kFailed : rc;
}

Action setup(Arguments& app) {
  auto o = std::make_shared<Options>();
  app.description(
      "Builds the chapter's program (cmake --build <build dir> --target chapter_NN, in the\n"
      "build directory this t2 belongs to; its messages go to stderr) and runs it with ARGS,\n"
      "e.g. `t2 run 01 --figures /tmp/fig`. NN may be 1, 01, the slug or NN-slug. The exit\n"
      "status is the program's.");
  app.add_flag("--no-build", o->no_build, "run the program as it is");
  app.add_option("NN", o->chapter, "the chapter (t2 list shows them)")->required();
  app.prefix_command();  // everything after NN goes to the program
  return [o, &app] { return run(*o, app.remaining()); };
}

}  // namespace cmd_run

T2_COMMAND({"run", "build and run the program of a chapter", cmd_run::setup});

}  // namespace t2cli
