// t2 book: build the HTML book; check and sync the listings cut from source files.
#include <fmt/format.h>

#include <memory>
#include <string>

#include "book_core.hpp"
#include "book_html.hpp"
#include "command.hpp"

namespace t2cli {
namespace cmd_book {

namespace fs = std::filesystem;

struct BookArgs {
  std::string action = "build";
  fs::path root = book::default_root();
  fs::path out, docs;
  fs::path programs;  // where chapter_NN are; empty: the own build's, if it was built from root
  bool quiet = false;
};

// The options that belong to one action only.
void check_options(const BookArgs& a) {
  if (a.action != "check" && !a.programs.empty()) throw UsageError("--programs is an option of `t2 book check`");
  if (a.action != "build" && (!a.out.empty() || !a.docs.empty()))
    throw UsageError("--out and --docs are options of `t2 book build`");
  if (!fs::is_directory(a.root / "chapters")) throw UsageError("no chapters/ folder in " + a.root.string());
}

void print_problems(const std::vector<book::Problem>& ps) {
  for (const auto& p : ps) fmt::print(stderr, "{}: {}\n", p.where, p.message);
}

int book_command(const BookArgs& a) {
  check_options(a);
  if (a.action == "check") {
    int listings = 0, outputs = 0;
    fs::path programs = a.programs;
    std::error_code ec;
    if (programs.empty() && fs::equivalent(a.root, book::default_root(), ec))
      programs = book::own_build_dir() / "bin";  // the programs were built from this root
    const auto ps = book::check_book(a.root, &listings, programs, &outputs);
    std::size_t chapters = 0;
    for (const auto& c : book::find_chapters(a.root)) chapters += c.has_text;
    if (!ps.empty()) {
      print_problems(ps);
      fmt::print(stderr, "t2 book check: {} problem(s) in {} chapter(s); `t2 book sync` rewrites listings from their source\n",
                 ps.size(), chapters);
      return kFailed;
    }
    if (!a.quiet) {
      fmt::print("t2 book check: {} chapter(s), {} listing(s), all in sync, every figure and link exists\n",
                 chapters, listings);
      if (programs.empty())
        fmt::print("t2 book check: quoted program output not checked (no --programs DIR for this root)\n");
      else
        fmt::print("t2 book check: {} quoted output block(s), each printed by its chapter program\n", outputs);
    }
    return kOk;
  }
  if (a.action == "sync") {
    std::vector<book::Problem> ps;
    const auto changed = book::sync_book(a.root, ps);
    for (const auto& f : changed) fmt::print("rewrote listings of {}\n", f);
    if (!ps.empty()) {
      print_problems(ps);
      return kFailed;
    }
    if (changed.empty() && !a.quiet) fmt::print("t2 book sync: every listing was already in sync\n");
    return kOk;
  }
  book::BuildOptions o;
  o.root = a.root;
  const fs::path build = book::own_build_dir();
  o.out = a.out.empty() ? build / "book" : a.out;
  if (!a.docs.empty()) {
    o.docs = a.docs;
  } else if (fs::exists(build / "docs" / "t2.tag")) {
    o.docs = build / "docs";
  } else {
    o.docs = a.root / "build" / "default" / "docs";
  }
  o.quiet = a.quiet;
  const int pages = book::build_book(o);
  fmt::print("t2 book: {} page(s); open {}\n", pages, (o.out / "index.html").string());
  return kOk;
}

Action setup(Arguments& app) {
  auto a = std::make_shared<BookArgs>();
  app.description(
      "ACTION is build (the default), check or sync; --out and --docs are options of build,\n"
      "--programs of check.\n"
      "\n"
      "build  Makes the HTML book with pandoc: a contents page by part, one page per chapter\n"
      "       (chapters/NN-slug/chapter.md and its later parts chapter-2.md, chapter-3.md ...\n"
      "       read as one document) with previous/next links, and one page per exercise sheet\n"
      "       (every exercises/NN-slug/ and exercises/NNx-slug/ with a README.md, linked from\n"
      "       the contents and from its chapter). Math is MathML, figures are copied, library\n"
      "       names in inline code link to the Doxygen reference (DIR/t2.tag and DIR/html;\n"
      "       default: the docs/ folder of this build). Default output:\n"
      "       <build>/book/index.html. Needs no server. Every `t2 animate ALGO FILE -o\n"
      "       NAME.html` command of a chapter (FILE relative to the root) is run as printed,\n"
      "       its page written to animations/NAME.html beside the chapters, which link to it\n"
      "       as ../../animations/NAME.html.\n"
      "check  Checks every part of every chapter. Fails (exit 1) when a listing differs from\n"
      "       the source region it is cut from, when a marker //> NAME ... //< NAME is missing,\n"
      "       when a figure or link target does not exist (a link to ../../animations/NAME.html:\n"
      "       when no chapter's t2 animate command writes NAME.html, or one cannot run),\n"
      "       when a line of a code block\n"
      "       (```text output excepted) is over 90 columns and would scroll in the HTML book,\n"
      "       or when the parts of a chapter skip a number or a later part has a '# Title'.\n"
      "       Prints chapter:line, listing and the first differing line.\n"
      "       It also runs each chapter program (figures to a scratch folder) and fails when a\n"
      "       ```text block of its chapter quotes a line the program does not print (the\n"
      "       block's lines must appear in the output in order; an excerpt is fine). The\n"
      "       programs are DIR/chapter_NN with --programs DIR, by default this build's bin/\n"
      "       when --root is the checkout t2 was built from (otherwise output is unchecked).\n"
      "sync   Rewrites every listing of every chapter from its source region.");
  app.add_option("ACTION", a->action, "build (the default), check or sync")
      ->check(IsMember({"build", "check", "sync"}));
  app.add_option("--out,-o", a->out, "build: the output folder (default <build>/book)")->type_name("DIR");
  app.add_option("--docs", a->docs, "build: the Doxygen output to link to (DIR/t2.tag, DIR/html)")->type_name("DIR");
  app.add_option("--programs", a->programs, "check: the folder of the chapter_NN programs")->type_name("DIR");
  app.add_option("--root", a->root, "work on another checkout (default: the one t2 was built from)")
      ->type_name("DIR");
  app.add_flag("--quiet,-q", a->quiet, "print only problems");
  app.footer(
      "A listing in chapter.md is the comment <!-- listing: PATH#NAME --> (PATH relative to\n"
      "the repository root) followed by a fenced code block; see chapters/README.md.");
  return [a] { return book_command(*a); };
}

}  // namespace cmd_book

T2_COMMAND({"book", "build the HTML book; check or sync its listings", cmd_book::setup});

}  // namespace t2cli
