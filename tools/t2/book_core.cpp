// The book system: chapters, named regions of source files, listings, link checks.
#include "book_core.hpp"

#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <iterator>
#include <memory>
#include <regex>
#include <sstream>
#include <stdexcept>

#include "t2/io.hpp"

namespace t2cli::book {

fs::path default_root() { return fs::path(T2_SOURCE_DIR); }

fs::path own_build_dir() {
  std::error_code ec;
  const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
  if (!ec) {
    const fs::path build = exe.parent_path().parent_path();
    if (fs::exists(build / "CMakeCache.txt", ec)) return build;
  }
  return fs::path(T2_BINARY_DIR);
}

std::string read_text(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  if (!in) throw std::runtime_error("cannot read " + p.string());
  return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

std::vector<std::string> split_lines(const std::string& text) {
  std::vector<std::string> lines;
  std::string cur;
  for (char c : text) {
    if (c == '\n') {
      if (!cur.empty() && cur.back() == '\r') cur.pop_back();
      lines.push_back(cur);
      cur.clear();
    } else {
      cur += c;
    }
  }
  if (!cur.empty()) lines.push_back(cur);
  return lines;
}

namespace {

std::string trim(const std::string& s) {
  const auto b = s.find_first_not_of(" \t\r");
  if (b == std::string::npos) return "";
  const auto e = s.find_last_not_of(" \t\r");
  return s.substr(b, e - b + 1);
}

std::string join_lines(const std::vector<std::string>& lines) {
  std::string out;
  for (const auto& l : lines) out += l + "\n";
  return out;
}

// "//> name" -> ('>', "name"); also "#> name" for CMake and shell files.
bool parse_marker(const std::string& line, char& kind, std::string& name) {
  const std::string t = trim(line);
  std::size_t p;
  if (t.rfind("//", 0) == 0) {
    p = 2;
  } else if (t.rfind("#", 0) == 0) {
    p = 1;
  } else {
    return false;
  }
  if (p >= t.size() || (t[p] != '>' && t[p] != '<')) return false;
  kind = t[p];
  name = trim(t.substr(p + 1));
  return !name.empty() && name.find_first_of(" \t") == std::string::npos;
}

}  // namespace

std::vector<Chapter> find_chapters(const fs::path& root) {
  std::vector<Chapter> out;
  const fs::path dir = root / "chapters";
  std::error_code ec;
  if (!fs::is_directory(dir, ec)) return out;
  static const std::regex folder_re(R"(^([0-9][0-9])-([a-z0-9][a-z0-9-]*)$)");
  for (const auto& e : fs::directory_iterator(dir)) {
    if (!e.is_directory()) continue;
    const std::string name = e.path().filename().string();
    std::smatch m;
    if (!std::regex_match(name, m, folder_re)) continue;
    Chapter c;
    c.number = m[1];
    c.slug = m[2];
    c.dir = e.path();
    c.has_text = fs::exists(c.dir / "chapter.md");
    c.has_program = fs::exists(c.dir / "main.cpp");
    if (c.has_text) {
      for (const auto& l : split_lines(read_text(c.dir / "chapter.md"))) {
        if (l.rfind("# ", 0) == 0) {
          c.title = trim(l.substr(2));
          break;
        }
      }
    }
    out.push_back(c);
  }
  std::sort(out.begin(), out.end(), [](const Chapter& a, const Chapter& b) { return a.folder() < b.folder(); });
  return out;
}

std::optional<Chapter> find_chapter(const fs::path& root, const std::string& name) {
  std::string n = name;
  if (n.size() == 1 && std::isdigit(static_cast<unsigned char>(n[0]))) n = "0" + n;
  for (const auto& c : find_chapters(root))
    if (n == c.number || n == c.slug || n == c.folder()) return c;
  return std::nullopt;
}

std::string cut_region(const std::string& source, const std::string& name, const std::string& file) {
  const auto lines = split_lines(source);
  std::optional<std::size_t> begin, end;
  for (std::size_t i = 0; i < lines.size(); ++i) {
    char kind;
    std::string n;
    if (!parse_marker(lines[i], kind, n) || n != name) continue;
    auto& slot = kind == '>' ? begin : end;
    if (slot)
      throw std::runtime_error(file + ":" + std::to_string(i + 1) + ": marker '" + std::string(kind == '>' ? "//> " : "//< ") +
                               name + "' appears twice");
    slot = i;
  }
  if (!begin) throw std::runtime_error(file + ": no marker line '//> " + name + "'");
  if (!end) throw std::runtime_error(file + ": no marker line '//< " + name + "'");
  if (*end < *begin)
    throw std::runtime_error(file + ":" + std::to_string(*end + 1) + ": '//< " + name + "' comes before '//> " + name + "'");
  std::vector<std::string> body;
  for (std::size_t i = *begin + 1; i < *end; ++i) {
    char kind;
    std::string n;
    if (parse_marker(lines[i], kind, n)) continue;  // markers of other (overlapping) regions
    std::string l = lines[i];
    while (!l.empty() && (l.back() == ' ' || l.back() == '\t')) l.pop_back();
    body.push_back(l);
  }
  std::size_t indent = std::string::npos;
  for (const auto& l : body)
    if (!l.empty()) indent = std::min(indent, l.find_first_not_of(" \t"));
  if (indent == std::string::npos) indent = 0;
  for (auto& l : body) l = l.size() >= indent ? l.substr(indent) : "";
  return join_lines(body);
}

namespace {

const std::regex& listing_re() {
  static const std::regex re(R"(^\s*<!--\s*listing:\s*([^#\s]+)#(\S+)\s*-->\s*$)");
  return re;
}

// A fence line: returns its character and length, or 0.
std::size_t fence_of(const std::string& line, char& ch) {
  std::size_t i = 0;
  while (i < line.size() && i < 3 && line[i] == ' ') ++i;
  if (i >= line.size() || (line[i] != '`' && line[i] != '~')) return 0;
  ch = line[i];
  std::size_t n = 0;
  while (i + n < line.size() && line[i + n] == ch) ++n;
  return n >= 3 ? n : 0;
}

std::string language_of(const std::string& path) {
  const std::string ext = fs::path(path).extension().string();
  if (ext == ".cpp" || ext == ".hpp" || ext == ".h" || ext == ".cc") return "cpp";
  if (ext == ".cmake" || fs::path(path).filename() == "CMakeLists.txt") return "cmake";
  if (ext == ".sh") return "sh";
  return "";
}

std::string shorten(const std::string& s) { return s.size() > 100 ? s.substr(0, 97) + "..." : s; }

}  // namespace

SyncResult sync_listings(const fs::path& root, const std::string& rel, const std::string& text) {
  SyncResult r;
  const auto lines = split_lines(text);
  std::vector<std::string> out;
  std::size_t i = 0;
  while (i < lines.size()) {
    std::smatch m;
    if (!std::regex_match(lines[i], m, listing_re())) {
      // Skip over fenced code blocks so that a listing comment shown *inside* a code block (as in
      // chapters/README.md) is not taken for a real one.
      char ch;
      const std::size_t n = fence_of(lines[i], ch);
      out.push_back(lines[i++]);
      if (n) {
        while (i < lines.size()) {
          char c2;
          const std::size_t n2 = fence_of(lines[i], c2);
          out.push_back(lines[i++]);
          if (n2 >= n && c2 == ch && trim(out.back()).find_first_not_of(ch) == std::string::npos) break;
        }
      }
      continue;
    }
    ++r.listings;
    const std::string where = rel + ":" + std::to_string(i + 1);
    const std::string src = m[1], name = m[2];
    out.push_back(lines[i++]);
    // The fenced block that follows, if any.
    char ch = '`';
    std::size_t n = i < lines.size() ? fence_of(lines[i], ch) : 0;
    std::string open = "```" + language_of(src);
    std::vector<std::string> old;
    bool had_block = false;
    if (n) {
      had_block = true;
      open = lines[i++];
      while (i < lines.size()) {
        char c2;
        const std::size_t n2 = fence_of(lines[i], c2);
        if (n2 >= n && c2 == ch && trim(lines[i]).find_first_not_of(ch) == std::string::npos) break;
        old.push_back(lines[i++]);
      }
      if (i >= lines.size()) {
        r.problems.push_back({where, "the code block of listing " + src + "#" + name + " is never closed"});
        r.text = text;
        return r;
      }
      ++i;  // closing fence
    }
    std::string region;
    try {
      const fs::path sp = root / src;
      if (!fs::exists(sp)) throw std::runtime_error("listing source " + src + " does not exist");
      region = cut_region(read_text(sp), name, src);
    } catch (const std::exception& e) {
      r.problems.push_back({where, std::string("listing ") + src + "#" + name + ": " + e.what()});
      out.push_back(open);
      for (const auto& l : old) out.push_back(l);
      out.push_back(std::string(std::max<std::size_t>(n, 3), ch));
      if (!had_block) out.pop_back(), out.pop_back();
      continue;
    }
    const auto want = split_lines(region);
    if (!had_block) {
      ++r.changed;
      r.problems.push_back({where, "listing " + src + "#" + name + " is not followed by a fenced code block"});
    } else if (want != old) {
      ++r.changed;
      std::size_t k = 0;
      while (k < want.size() && k < old.size() && want[k] == old[k]) ++k;
      std::string msg = "listing " + src + "#" + name + " differs from its source at line " + std::to_string(k + 1) +
                        " of the listing (file line " + std::to_string(i - old.size() + k) + ")\n";
      msg += "    book:   " + (k < old.size() ? shorten(old[k]) : std::string("(listing ends here)")) + "\n";
      msg += "    source: " + (k < want.size() ? shorten(want[k]) : std::string("(region ends here)"));
      r.problems.push_back({where, msg});
    }
    out.push_back(open);
    for (const auto& l : want) out.push_back(l);
    out.push_back(std::string(std::max<std::size_t>(n, 3), ch));
  }
  r.text = join_lines(out);
  return r;
}

std::vector<LinkRef> local_links(const std::string& text) {
  std::vector<LinkRef> out;
  static const std::regex link_re(R"((!?)\[[^\]]*\]\(\s*<?([^)\s>]+)>?(?:\s+"[^"]*")?\s*\))");
  static const std::regex scheme_re(R"(^[a-zA-Z][a-zA-Z0-9+.-]*:)");
  const auto lines = split_lines(text);
  char fch = 0;
  std::size_t flen = 0;
  bool in_comment = false;
  for (std::size_t i = 0; i < lines.size(); ++i) {
    std::string l = lines[i];
    char ch;
    const std::size_t n = fence_of(l, ch);
    if (flen) {
      if (n >= flen && ch == fch && trim(l).find_first_not_of(ch) == std::string::npos) flen = 0;
      continue;
    }
    if (n) {
      fch = ch;
      flen = n;
      continue;
    }
    // Remove HTML comments and inline code spans.
    std::string s;
    for (std::size_t k = 0; k < l.size();) {
      if (in_comment) {
        const auto e = l.find("-->", k);
        if (e == std::string::npos) {
          k = l.size();
        } else {
          in_comment = false;
          k = e + 3;
        }
      } else if (l.compare(k, 4, "<!--") == 0) {
        in_comment = true;
        k += 4;
      } else if (l[k] == '`') {
        std::size_t run = 0;
        while (k + run < l.size() && l[k + run] == '`') ++run;
        const auto e = l.find(std::string(run, '`'), k + run);
        if (e == std::string::npos) {
          k += run;
        } else {
          k = e + run;
        }
        s += ' ';
      } else {
        s += l[k++];
      }
    }
    for (auto it = std::sregex_iterator(s.begin(), s.end(), link_re); it != std::sregex_iterator(); ++it) {
      std::string target = (*it)[2];
      if (target.empty() || target[0] == '#' || std::regex_search(target, scheme_re)) continue;
      const auto hash = target.find('#');
      if (hash != std::string::npos) target.resize(hash);
      out.push_back({i, target, (*it)[1].length() > 0});
    }
  }
  return out;
}

std::vector<std::string> chapter_markdown_files(const fs::path& root) {
  std::vector<std::string> out;
  for (const auto& c : find_chapters(root))
    if (c.has_text) out.push_back("chapters/" + c.folder() + "/chapter.md");
  return out;
}

namespace {

std::vector<Problem> check_one(const fs::path& root, const std::string& rel, const std::string& text) {
  std::vector<Problem> ps;
  const auto lines = split_lines(text);
  if (lines.empty() || lines[0].rfind("# ", 0) != 0)
    ps.push_back({rel + ":1", "the first line must be the chapter title, '# Title'"});
  const fs::path dir = (root / rel).parent_path();
  for (const auto& link : local_links(text)) {
    std::error_code ec;
    if (!fs::exists(dir / link.target, ec))
      ps.push_back({rel + ":" + std::to_string(link.line + 1),
                    std::string(link.image ? "figure " : "link target ") + link.target + " does not exist"});
  }
  return ps;
}

}  // namespace

std::vector<OutputBlock> output_blocks(const std::string& text) {
  std::vector<OutputBlock> out;
  const auto lines = split_lines(text);
  for (std::size_t i = 0; i < lines.size(); ++i) {
    if (lines[i] != "```text") continue;
    OutputBlock b;
    b.line = static_cast<int>(i);
    for (++i; i < lines.size() && lines[i].rfind("```", 0) != 0; ++i) {
      std::string l = lines[i];
      l.erase(l.find_last_not_of(" \t\r") + 1);
      if (!l.empty()) b.lines.push_back(std::move(l));
    }
    out.push_back(std::move(b));
  }
  return out;
}

std::vector<Problem> check_outputs(const std::string& rel, const std::string& text, const std::string& output,
                                   const std::string& program) {
  std::vector<std::string> printed;
  for (std::string l : split_lines(output)) {
    l.erase(l.find_last_not_of(" \t\r") + 1);
    printed.push_back(std::move(l));
  }
  std::vector<Problem> ps;
  for (const OutputBlock& b : output_blocks(text)) {
    std::size_t at = 0;  // the next printed line to look at: block lines must come in order
    for (std::size_t k = 0; k < b.lines.size(); ++k) {
      const auto it = std::find(printed.begin() + static_cast<std::ptrdiff_t>(at), printed.end(), b.lines[k]);
      if (it == printed.end()) {
        ps.push_back({rel + ":" + std::to_string(b.line + 2 + static_cast<int>(k)),
                      "the output block quotes a line that " + program + " does not print" +
                          (k ? " (after the block's previous lines)" : "") + ": '" + b.lines[k] + "'"});
        break;
      }
      at = static_cast<std::size_t>(it - printed.begin()) + 1;
    }
  }
  return ps;
}

std::vector<Problem> check_book(const fs::path& root, int* listings, const fs::path& programs, int* outputs) {
  std::vector<Problem> ps;
  if (listings) *listings = 0;
  if (outputs) *outputs = 0;
  for (const auto& rel : chapter_markdown_files(root)) {
    const std::string text = read_text(root / rel);
    auto r = sync_listings(root, rel, text);
    if (listings) *listings += r.listings;
    ps.insert(ps.end(), r.problems.begin(), r.problems.end());
    auto more = check_one(root, rel, text);
    ps.insert(ps.end(), more.begin(), more.end());
  }
  if (programs.empty()) return ps;
  for (const auto& c : find_chapters(root)) {
    if (!c.has_text || !c.has_program) continue;
    const std::string rel = "chapters/" + c.folder() + "/chapter.md";
    const std::string text = read_text(root / rel);
    if (output_blocks(text).empty()) continue;
    const std::string name = "chapter_" + c.number;
    const fs::path exe = programs / name;
    if (!fs::exists(exe)) {
      ps.push_back({rel + ":1", name + " is not built in " + programs.string() + ": its output blocks are unchecked"});
      continue;
    }
    // Figures go to a scratch directory: checking the book must not touch the repository.
    const fs::path scratch = fs::temp_directory_path() / ("t2-book-check-" + std::to_string(::getpid()) + "-" + c.number);
    std::string out, err;
    const int status = run_program_capture({exe.string(), "--figures", scratch.string()}, out, err);
    std::error_code ec;
    fs::remove_all(scratch, ec);
    if (status != 0) {
      ps.push_back({rel + ":1", name + " failed (exit status " + std::to_string(status) +
                                    "): its output blocks are unchecked; it said: " + err});
      continue;
    }
    if (outputs) *outputs += static_cast<int>(output_blocks(text).size());
    auto more = check_outputs(rel, text, out, name);
    ps.insert(ps.end(), more.begin(), more.end());
  }
  return ps;
}

std::vector<std::string> sync_book(const fs::path& root, std::vector<Problem>& problems) {
  std::vector<std::string> changed;
  for (const auto& rel : chapter_markdown_files(root)) {
    const std::string text = read_text(root / rel);
    auto r = sync_listings(root, rel, text);
    for (const auto& p : r.problems)
      if (p.message.find("differs from its source") == std::string::npos &&
          p.message.find("not followed by a fenced") == std::string::npos)
        problems.push_back(p);
    if (r.text != text) {
      t2::write_file_atomically(root / rel, r.text);
      changed.push_back(rel);
    }
  }
  return changed;
}

namespace {
/// Runs argv[0] (no shell) with its standard output on `out_fd` and its standard error on
/// `err_fd` (-1: inherited) and waits.
int spawn_and_wait(const std::vector<std::string>& argv, int out_fd, int err_fd = -1) {
  std::vector<char*> a;
  for (const auto& s : argv) a.push_back(const_cast<char*>(s.c_str()));
  a.push_back(nullptr);
  std::fflush(nullptr);
  const pid_t pid = ::fork();
  if (pid < 0) return -1;
  if (pid == 0) {
    if (out_fd >= 0) ::dup2(out_fd, 1);
    if (err_fd >= 0) ::dup2(err_fd, 2);
    ::execvp(a[0], a.data());
    std::fprintf(stderr, "cannot run %s: %s\n", a[0], std::strerror(errno));
    ::_exit(127);
  }
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0) {
    if (errno != EINTR) return -1;
  }
  if (WIFEXITED(status)) return WEXITSTATUS(status) == 127 ? -1 : WEXITSTATUS(status);
  if (WIFSIGNALED(status)) return 128 + WTERMSIG(status);
  return -1;
}
}  // namespace

int run_program(const std::vector<std::string>& argv, bool stdout_to_stderr) {
  return spawn_and_wait(argv, stdout_to_stderr ? 2 : -1);
}

int run_program_capture(const std::vector<std::string>& argv, std::string& out, std::string& err) {
  // The child writes to unlinked temporary files (a pipe could fill up while we wait).
  using File = std::unique_ptr<std::FILE, int (*)(std::FILE*)>;
  File o(std::tmpfile(), &std::fclose), e(std::tmpfile(), &std::fclose);
  if (!o || !e) return -1;
  const int status = spawn_and_wait(argv, ::fileno(o.get()), ::fileno(e.get()));
  for (auto [f, text] : {std::pair{o.get(), &out}, std::pair{e.get(), &err}}) {
    std::rewind(f);
    text->clear();
    char buf[1 << 14];
    std::size_t n;
    while ((n = std::fread(buf, 1, sizeof buf, f)) > 0) text->append(buf, n);
  }
  return status;
}

}  // namespace t2cli::book
