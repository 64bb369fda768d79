// The book system: chapters, named regions of source files, running programs.
#include "book_core.hpp"

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <regex>
#include <stdexcept>

#include "process.hpp"
#include "t2/kernel/io.hpp"

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

std::string join_lines(const std::vector<std::string>& lines) {
  std::string out;
  for (const auto& l : lines) out += l + "\n";
  return out;
}

namespace {

// "//> name" -> ('>', "name"); also "#> name" for CMake and shell files.
bool parse_marker(const std::string& line, char& kind, std::string& name) {
  const std::string t = t2::trim(line);
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
  name = t2::trim(t.substr(p + 1));
  return !name.empty() && name.find_first_of(" \t") == std::string::npos;
}

// chapter.md, then chapter-K.md (K >= 2) in the order of K; nothing without chapter.md.
std::vector<std::string> text_parts(const fs::path& dir) {
  if (!fs::exists(dir / "chapter.md")) return {};
  static const std::regex part_re(R"(^chapter-([0-9]+)\.md$)");
  std::vector<std::pair<unsigned long, std::string>> more;
  for (const auto& e : fs::directory_iterator(dir)) {
    const std::string name = e.path().filename().string();
    std::smatch m;
    if (e.is_regular_file() && std::regex_match(name, m, part_re)) more.emplace_back(std::stoul(m[1]), name);
  }
  std::sort(more.begin(), more.end());
  std::vector<std::string> out{"chapter.md"};
  for (const auto& [k, name] : more) out.push_back(name);
  return out;
}

// exercises/NN-slug and exercises/NNx-slug (x one letter) that hold a README.md, sorted.
std::vector<std::string> exercise_folders(const fs::path& root, const std::string& number) {
  std::vector<std::string> out;
  std::error_code ec;
  if (!fs::is_directory(root / "exercises", ec)) return out;
  static const std::regex folder_re(R"(^([0-9][0-9])[a-z]?-[a-z0-9][a-z0-9-]*$)");
  for (const auto& e : fs::directory_iterator(root / "exercises")) {
    const std::string name = e.path().filename().string();
    std::smatch m;
    if (e.is_directory() && std::regex_match(name, m, folder_re) && m[1] == number &&
        fs::exists(e.path() / "README.md"))
      out.push_back(name);
  }
  std::sort(out.begin(), out.end());
  return out;
}

}  // namespace

std::string part_file(std::size_t k) { return k <= 1 ? "chapter.md" : "chapter-" + std::to_string(k) + ".md"; }

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
    c.parts = text_parts(c.dir);
    c.exercises = exercise_folders(root, c.number);
    if (c.has_text) {
      for (const auto& l : split_lines(t2::read_file(c.dir / "chapter.md"))) {
        if (l.rfind("# ", 0) == 0) {
          c.title = t2::trim(l.substr(2));
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

int run_program(const std::vector<std::string>& argv, bool stdout_to_stderr) {
  std::fflush(nullptr);  // what t2 printed comes before what the program prints
  t2proc::Spec s;
  s.argv = argv;
  s.out = stdout_to_stderr ? t2proc::Stream::capture : t2proc::Stream::inherit;
  s.err = t2proc::Stream::inherit;
  s.inherit_stdin = !stdout_to_stderr;
  const t2proc::Result r = t2proc::run(s);
  if (stdout_to_stderr) std::fwrite(r.out.data(), 1, r.out.size(), stderr);
  if (!r.started) return -1;
  return r.signal ? 128 + r.signal : r.exit_code;
}

}  // namespace t2cli::book
