// `t2 book build`: runs pandoc once per page with book/template.html and book/book.lua.
#include "book_html.hpp"

#include <fmt/format.h>

#include <cstdio>
#include <cstring>
#include <fstream>
#include <regex>
#include <sstream>
#include <stdexcept>
#include <vector>

#include "book_animations.hpp"
#include "book_ast.hpp"
#include "book_core.hpp"
#include "t2/kernel/io.hpp"

namespace t2cli::book {

namespace {

std::string html_escape(const std::string& s) {
  std::string o;
  for (char c : s) {
    switch (c) {
      case '&': o += "&amp;"; break;
      case '<': o += "&lt;"; break;
      case '>': o += "&gt;"; break;
      case '"': o += "&quot;"; break;
      default: o += c;
    }
  }
  return o;
}

std::string xml_unescape(std::string s) {
  const std::pair<const char*, const char*> rep[] = {{"&lt;", "<"}, {"&gt;", ">"}, {"&quot;", "\""}, {"&apos;", "'"}, {"&amp;", "&"}};
  for (const auto& [from, to] : rep) {
    std::string::size_type p = 0;
    while ((p = s.find(from, p)) != std::string::npos) {
      s.replace(p, std::strlen(from), to);
      p += std::strlen(to);
    }
  }
  return s;
}

struct CoursePart {
  std::string numeral, title;
  int first = 0, last = 0;
};

std::vector<CoursePart> read_parts(const fs::path& file) {
  std::vector<CoursePart> parts;
  if (!fs::exists(file)) return parts;
  static const std::regex re(R"(^\s*([IVXL]+)\s+([0-9]+)\s+([0-9]+)\s+(.+?)\s*$)");
  for (const auto& l : split_lines(t2::read_file(file))) {
    std::smatch m;
    if (l.empty() || l[0] == '#' || !std::regex_match(l, m, re)) continue;
    parts.push_back({m[1], m[4], std::stoi(m[2]), std::stoi(m[3])});
  }
  return parts;
}

// a/b relative to base, with forward slashes ("../../docs/html").
std::string rel(const fs::path& target, const fs::path& base) {
  std::error_code ec;
  const fs::path r = fs::relative(fs::weakly_canonical(target, ec), fs::weakly_canonical(base, ec), ec);
  if (ec || r.empty()) return fs::absolute(target).generic_string();
  return r.generic_string();
}

void copy_tree(const fs::path& from, const fs::path& to) {
  if (!fs::is_directory(from)) return;
  for (const auto& e : fs::recursive_directory_iterator(from)) {
    const fs::path dst = to / fs::relative(e.path(), from);
    if (e.is_directory()) {
      fs::create_directories(dst);
    } else if (e.is_regular_file()) {
      fs::create_directories(dst.parent_path());
      fs::copy_file(e.path(), dst, fs::copy_options::overwrite_existing);
    }
  }
}

// The page of the exercise folder "01b-t1-order": "exercises-01b-t1-order.html".
std::string exercise_page(const std::string& folder) { return "exercises-" + folder + ".html"; }

// How the book names that sheet: "01b" (the folder's name up to its first '-').
std::string sheet_label(const std::string& folder) { return folder.substr(0, folder.find('-')); }

}  // namespace

std::map<std::string, std::string> read_tag_file(const fs::path& tag) {
  std::map<std::string, std::string> out;
  if (!fs::exists(tag)) return out;
  // A small state machine over the tag file's lines: compounds hold names, members.
  static const std::regex compound_re(R"re(<compound kind="([a-z]+)">)re");
  static const std::regex field_re(R"(^\s*<(name|filename|anchorfile|anchor)>(.*)</\1>\s*$)");
  std::string kind, cname, cfile;
  bool in_member = false;
  std::string mname, mfile, manchor;
  for (const auto& l : split_lines(t2::read_file(tag))) {
    std::smatch m;
    if (std::regex_search(l, m, compound_re)) {
      kind = m[1];
      cname.clear();
      cfile.clear();
      continue;
    }
    if (l.find("<member ") != std::string::npos) {
      in_member = true;
      mname.clear();
      mfile.clear();
      manchor.clear();
      continue;
    }
    if (l.find("</member>") != std::string::npos) {
      in_member = false;
      if (mname.empty() || mfile.empty()) continue;
      std::string full;
      if (kind == "file" || kind == "namespace")
        full = "t2::" + mname;
      else if (kind == "class" || kind == "struct")
        full = cname + "::" + mname;
      else
        continue;
      out.emplace(full, mfile + (manchor.empty() ? "" : "#" + manchor));
      continue;
    }
    if (l.find("</compound>") != std::string::npos) {
      if ((kind == "class" || kind == "struct") && !cname.empty() && !cfile.empty()) out[cname] = cfile;
      kind.clear();
      continue;
    }
    if (std::regex_match(l, m, field_re)) {
      const std::string f = m[1], v = xml_unescape(m[2]);
      if (in_member) {
        if (f == "name") mname = v;
        if (f == "anchorfile") mfile = v;
        if (f == "anchor") manchor = v;
      } else {
        if (f == "name" && cname.empty()) cname = v;
        if (f == "filename") cfile = v;
      }
    }
  }
  return out;
}

int build_book(const BuildOptions& o) {
  const fs::path bookdir = o.root / "book";
  for (const char* f : {"template.html", "book.lua", "style.css"})
    if (!fs::exists(bookdir / f)) throw std::runtime_error("missing " + (bookdir / f).string());
  fs::create_directories(o.out);

  // The API map for the Lua filter: name, tab, href relative to the output directory.
  const auto api = read_tag_file(o.docs / "t2.tag");
  if (api.empty() && !o.quiet)
    fmt::print(stderr, "t2 book: no API tag file at {} (build the `docs` target): names stay unlinked\n",
               (o.docs / "t2.tag").string());
  const std::string html_rel = rel(o.docs / "html", o.out);
  std::string tsv;
  for (const auto& [name, href] : api) tsv += name + "\t" + html_rel + "/" + href + "\n";
  const fs::path work = o.out / ".book-build";
  fs::create_directories(work);
  t2::update_file_atomically(work / "api.tsv", tsv);

  copy_tree(o.root / "figures", o.out / "figures");
  std::vector<Problem> bad;  // the chapters' animations, beside the figures
  const auto animations = find_animations(o.root, bad);
  if (!bad.empty()) throw std::runtime_error(bad.front().where + ": " + bad.front().message);
  build_animations(o.root, animations, o.out, o.quiet);
  fs::copy_file(bookdir / "style.css", o.out / "style.css", fs::copy_options::overwrite_existing);

  const std::string reporel = rel(o.root, o.out);
  // One page from one or more markdown files (the parts of a chapter), read as one document.
  auto pandoc = [&](const std::vector<fs::path>& inputs, const fs::path& output, const std::string& srcdir,
                    const std::string& pagetitle, const std::vector<std::pair<std::string, std::string>>& vars,
                    bool toc) {
    std::vector<std::string> argv = {"pandoc", std::string("--from=") + kPandocReader,
                                     "--to=html5", "--standalone", "--mathml", "--wrap=none",
                                     "--template=" + (bookdir / "template.html").string(),
                                     "--lua-filter=" + (bookdir / "book.lua").string(),
                                     "--highlight-style=tango",
                                     "--metadata=pagetitle:" + pagetitle,
                                     "--metadata=reporel:" + reporel,
                                     "--metadata=apimap:" + (work / "api.tsv").string(),
                                     "--output=" + output.string()};
    if (!srcdir.empty()) argv.push_back("--metadata=srcdir:" + srcdir);
    if (toc) argv.insert(argv.end(), {"--toc", "--toc-depth=2"});
    for (const auto& [k, v] : vars) argv.push_back("--variable=" + k + ":" + v);
    for (const auto& in : inputs) argv.push_back(in.string());
    const int rc = run_program(argv);
    if (rc != 0)
      throw std::runtime_error(rc < 0 ? "cannot run pandoc (install the Debian package pandoc)"
                                      : "pandoc failed on " + inputs.front().string());
    if (!o.quiet) fmt::print("  {}\n", output.string());
  };

  std::vector<Chapter> chapters;
  for (const auto& c : find_chapters(o.root))
    if (c.has_text) chapters.push_back(c);

  int pages = 0;
  for (std::size_t i = 0; i < chapters.size(); ++i) {
    const Chapter& c = chapters[i];
    const std::string title = c.title.empty() ? c.slug : c.title;
    std::vector<std::pair<std::string, std::string>> vars = {{"chapter_number", c.number}};
    if (i > 0) {
      vars.push_back({"prev", chapters[i - 1].folder() + ".html"});
      vars.push_back({"prev_title", html_escape(chapters[i - 1].number + " " + chapters[i - 1].title)});
    }
    if (i + 1 < chapters.size()) {
      vars.push_back({"next", chapters[i + 1].folder() + ".html"});
      vars.push_back({"next_title", html_escape(chapters[i + 1].number + " " + chapters[i + 1].title)});
    }
    // Every exercise sheet of the chapter: a page, and a link in the chapter's bar (a list
    // variable: the template repeats the link once per sheet).
    for (const auto& ex : c.exercises) {
      vars.push_back({"exercises", fmt::format("<a class=\"exercises\" href=\"{}\">Exercises {}</a>",
                                               exercise_page(ex), html_escape(sheet_label(ex)))});
      pandoc({o.root / "exercises" / ex / "README.md"}, o.out / exercise_page(ex), "exercises/" + ex,
             "Exercises " + sheet_label(ex) + " of chapter " + c.number + " — t2",
             {{"chapter_number", c.number}, {"up", c.folder() + ".html"}, {"up_title", html_escape(c.number + " " + title)}},
             false);
      ++pages;
    }
    std::vector<fs::path> parts;
    for (const auto& part : c.parts) parts.push_back(c.dir / part);
    pandoc(parts, o.out / (c.folder() + ".html"), "chapters/" + c.folder(), c.number + " " + title + " — t2", vars,
           true);
    ++pages;
  }

  // The contents page, by part.
  std::ostringstream md;
  md << "# t2 — computational geometry in the oriented projective plane T²\n\n"
     << "A literate course: each chapter explains one topic of the oriented projective plane T² "
        "and comes with a small program (run it with `t2 run NN`) that prints the numbers the "
        "text discusses and draws the figures, in the planar and in the spherical model. "
        "Each chapter ends with graded exercises.\n\n";
  const auto parts = read_parts(bookdir / "parts.txt");
  std::vector<bool> listed(chapters.size(), false);
  auto item = [&](std::size_t i) {
    const Chapter& c = chapters[i];
    listed[i] = true;
    md << "- " << c.number << " · [" << (c.title.empty() ? c.slug : c.title) << "](" << c.folder() << ".html)";
    for (std::size_t k = 0; k < c.exercises.size(); ++k)
      md << (k == 0 ? " · exercises " : ", ") << "[" << sheet_label(c.exercises[k]) << "]("
         << exercise_page(c.exercises[k]) << ")";
    md << "\n";
  };
  for (const auto& p : parts) {
    std::vector<std::size_t> in;
    for (std::size_t i = 0; i < chapters.size(); ++i) {
      const int n = std::stoi(chapters[i].number);
      if (n >= p.first && n <= p.last) in.push_back(i);
    }
    if (in.empty()) continue;
    md << "## Part " << p.numeral << " — " << p.title << "\n\n";
    for (auto i : in) item(i);
    md << "\n";
  }
  bool other = false;
  for (std::size_t i = 0; i < chapters.size(); ++i)
    if (!listed[i]) {
      if (!other) md << "## Other chapters\n\n";
      other = true;
      item(i);
    }
  if (!api.empty()) md << "\nThe [API reference](" << html_rel << "/index.html) documents every name of the library.\n";
  t2::update_file_atomically(work / "index.md", md.str());
  pandoc({work / "index.md"}, o.out / "index.html", "", "t2 — the book", {{"contents", "1"}}, false);
  ++pages;
  return pages;
}

}  // namespace t2cli::book
