// The links, images and code blocks of a chapter, from pandoc's JSON AST.
#include "book_ast.hpp"

#include <algorithm>
#include <cctype>
#include <nlohmann/json.hpp>
#include <stdexcept>

#include "process.hpp"

namespace t2cli::book {

namespace {

using json = nlohmann::json;

// %20 -> ' ': pandoc percent-encodes what a URL may not hold; files have the plain name.
std::string percent_decoded(const std::string& s) {
  std::string out;
  for (std::size_t i = 0; i < s.size(); ++i) {
    if (s[i] == '%' && i + 2 < s.size() && std::isxdigit(static_cast<unsigned char>(s[i + 1])) &&
        std::isxdigit(static_cast<unsigned char>(s[i + 2]))) {
      out += static_cast<char>(std::stoi(s.substr(i + 1, 2), nullptr, 16));
      i += 2;
    } else {
      out += s[i];
    }
  }
  return out;
}

// "http:", "mailto:", ... (RFC 3986: a letter, then letters, digits, + . -, then a colon).
bool has_scheme(const std::string& s) {
  const auto colon = s.find(':');
  if (colon == std::string::npos || colon == 0 || !std::isalpha(static_cast<unsigned char>(s[0]))) return false;
  return std::all_of(s.begin(), s.begin() + static_cast<std::ptrdiff_t>(colon), [](char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || c == '+' || c == '.' || c == '-';
  });
}

// Every element of the AST, depth first, which is document order.
void walk(const json& node, Document& doc) {
  if (node.is_array()) {
    for (const auto& n : node) walk(n, doc);
    return;
  }
  if (!node.is_object()) return;
  const auto t = node.find("t");
  const auto c = node.find("c");
  if (t == node.end() || !t->is_string()) {
    for (const auto& [k, v] : node.items()) walk(v, doc);
    return;
  }
  const std::string& type = t->get_ref<const std::string&>();
  if ((type == "Link" || type == "Image") && c != node.end()) {
    // [attr, inlines, [url, title]]
    const std::string url = (*c)[2][0].get<std::string>();
    LinkRef l;
    l.image = type == "Image";
    l.local = !url.empty() && url[0] != '#' && !has_scheme(url);
    l.target = percent_decoded(url.substr(0, url.find('#')));
    l.url = url;
    doc.links.push_back(std::move(l));
    walk((*c)[1], doc);  // an image inside a link
    return;
  }
  if (type == "CodeBlock" && c != node.end()) {
    // [[id, classes, key-values], text]
    CodeBlock b;
    for (const auto& cls : (*c)[0][1]) b.classes.push_back(cls.get<std::string>());
    b.code = (*c)[1].get<std::string>();
    doc.code_blocks.push_back(std::move(b));
    return;
  }
  if (c != node.end()) walk(*c, doc);
}

// The 1-based line of `text` at or after `from` (0-based) holding `needle`; else the first
// anywhere; else 0.
int find_line(const std::vector<std::string>& lines, std::size_t from, const std::string& needle) {
  for (std::size_t pass = 0; pass < 2; ++pass)
    for (std::size_t i = pass ? 0 : from; i < lines.size(); ++i)
      if (lines[i].find(needle) != std::string::npos) return static_cast<int>(i) + 1;
  return 0;
}

// The 1-based line where the code of `b` starts: after the first fence at or after `from`
// whose following lines are its code (a fence indented by n spaces strips up to n from each).
int find_code(const std::vector<std::string>& lines, std::size_t from, const CodeBlock& b) {
  const auto code = split_lines(b.code);
  for (std::size_t f = from; f < lines.size(); ++f) {
    char ch;
    if (!fence_of(lines[f], ch)) continue;
    const std::size_t indent = lines[f].find_first_not_of(' ');
    bool same = f + code.size() < lines.size();
    for (std::size_t j = 0; same && j < code.size(); ++j) {
      const std::string& l = lines[f + 1 + j];
      const std::size_t strip = std::min(indent, std::min(l.size(), l.find_first_not_of(' ')));
      same = l.substr(strip) == code[j];
    }
    if (same) return static_cast<int>(f) + 2;
  }
  return 0;
}

}  // namespace

Document parse_markdown(const std::string& text, const std::string& where) {
  t2proc::Spec s;
  s.argv = {"pandoc", std::string("--from=") + kPandocReader, "--to=json"};
  s.stdin_data = text;
  const t2proc::Result r = t2proc::run(s);
  if (!r.started) throw std::runtime_error("cannot run pandoc (install the Debian package pandoc): " + r.error);
  if (!r.ok()) throw std::runtime_error(where + ": pandoc failed: " + r.err);
  Document doc;
  walk(json::parse(r.out), doc);
  // Where each one is written: searched in order, so that a target written twice is placed right.
  const auto lines = split_lines(text);
  std::size_t at = 0;
  for (auto& l : doc.links) {
    int n = find_line(lines, at, l.target);
    if (!n) n = find_line(lines, at, l.url.substr(0, l.url.find('#')));  // written %-encoded
    l.line = n ? n : 1;
    if (n) at = static_cast<std::size_t>(n - 1);
  }
  at = 0;
  for (auto& b : doc.code_blocks) {
    const int n = find_code(lines, at, b);
    b.line = n ? n : 1;
    if (n) at = static_cast<std::size_t>(n - 1);
  }
  return doc;
}

std::vector<OutputBlock> output_blocks(const Document& doc) {
  std::vector<OutputBlock> out;
  for (const auto& b : doc.code_blocks) {
    if (b.classes.empty() || b.classes.front() != "text") continue;
    OutputBlock o;
    const auto lines = split_lines(b.code);
    for (std::size_t k = 0; k < lines.size(); ++k) {
      std::string l = lines[k];
      l.erase(l.find_last_not_of(" \t\r") + 1);
      if (l.empty()) continue;
      o.lines.push_back(std::move(l));
      o.line_of.push_back(b.line + static_cast<int>(k));
    }
    out.push_back(std::move(o));
  }
  return out;
}

std::vector<Problem> check_outputs(const std::string& rel, const std::vector<OutputBlock>& blocks,
                                   const std::string& output, const std::string& program) {
  std::vector<std::string> printed;
  for (std::string l : split_lines(output)) {
    l.erase(l.find_last_not_of(" \t\r") + 1);
    printed.push_back(std::move(l));
  }
  std::vector<Problem> ps;
  for (const OutputBlock& b : blocks) {
    std::size_t at = 0;  // the next printed line to look at: block lines must come in order
    for (std::size_t k = 0; k < b.lines.size(); ++k) {
      const auto it = std::find(printed.begin() + static_cast<std::ptrdiff_t>(at), printed.end(), b.lines[k]);
      if (it == printed.end()) {
        ps.push_back({rel + ":" + std::to_string(b.line_of[k]),
                      "the output block quotes a line that " + program + " does not print" +
                          (k ? " (after the block's previous lines)" : "") + ": '" + b.lines[k] + "'"});
        break;
      }
      at = static_cast<std::size_t>(it - printed.begin()) + 1;
    }
  }
  return ps;
}

std::vector<Problem> check_links(const fs::path& root, const std::string& rel, const Document& doc,
                                 const std::set<std::string>& animations) {
  std::vector<Problem> ps;
  const fs::path dir = (root / rel).parent_path();
  for (const auto& link : doc.links) {
    std::error_code ec;
    if (!link.local || link.target.empty()) continue;
    // animations/NAME.html of the book: written by a chapter's t2 animate command (book_animations.hpp).
    const fs::path in_root = (fs::path(rel).parent_path() / link.target).lexically_normal();
    if (in_root.parent_path() == "animations" && !link.image) {
      if (!animations.count(in_root.filename().string()))
        ps.push_back({rel + ":" + std::to_string(link.line),
                      "link target " + link.target + ": no chapter's t2 animate command writes " + in_root.string()});
      continue;
    }
    if (fs::exists(dir / link.target, ec)) continue;
    ps.push_back({rel + ":" + std::to_string(link.line),
                  std::string(link.image ? "figure " : "link target ") + link.target + " does not exist"});
  }
  return ps;
}

}  // namespace t2cli::book
