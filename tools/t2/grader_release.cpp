// Releases: see grader_release.hpp.
#include "grader_release.hpp"

#include <algorithm>
#include <cstdint>
#include <fstream>
#include <set>
#include <sstream>
#include <stdexcept>
#include <unordered_map>

#include <fmt/format.h>

namespace t2grader {

namespace fs = std::filesystem;

namespace {

std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

std::string trim(const std::string& s) {
  const auto b = s.find_first_not_of(" \t\r\n");
  if (b == std::string::npos) return {};
  return s.substr(b, s.find_last_not_of(" \t\r\n") - b + 1);
}

std::vector<fs::path> files_under(const fs::path& d) {
  std::vector<fs::path> r;
  std::error_code ec;
  if (!fs::is_directory(d, ec)) return r;
  for (auto it = fs::recursive_directory_iterator(d, ec); it != fs::recursive_directory_iterator(); it.increment(ec))
    if (it->is_regular_file()) r.push_back(it->path());
  std::sort(r.begin(), r.end());
  return r;
}

// Which of many lines occur in a text, in one pass over the text (Rabin-Karp): a rolling hash of
// every window of k characters (k the length of the shortest line) is looked up among the hashes
// of the lines' first k characters, and a hit is confirmed by comparing the whole line. One
// string::find per line and text read the whole source tree once per secret line (seconds of
// CPU, tens of seconds under the sanitizers).
class LineSet {
 public:
  explicit LineSet(const std::vector<std::string>& lines) : lines_(lines) {
    k_ = lines.empty() ? 0 : lines.front().size();
    for (const auto& l : lines) k_ = std::min(k_, l.size());
    for (std::size_t k = 0; k < k_; ++k) top_ *= kBase;  // kBase^k_
    for (std::size_t i = 0; i < lines.size(); ++i) first_[hash(lines[i].data())].push_back(i);
  }

  /// found[i]: lines[i] occurs in `text` (the empty line occurs everywhere).
  std::vector<bool> in(const std::string& text) const {
    std::vector<bool> found(lines_.size(), k_ == 0);
    if (k_ == 0 || text.size() < k_) return found;
    std::uint64_t h = hash(text.data());
    for (std::size_t at = 0;; ++at) {
      if (const auto it = first_.find(h); it != first_.end())
        for (std::size_t i : it->second)
          if (!found[i] && text.compare(at, lines_[i].size(), lines_[i]) == 0) found[i] = true;
      if (at + k_ >= text.size()) break;
      h = h * kBase + byte(text[at + k_]) - top_ * byte(text[at]);
    }
    return found;
  }

 private:
  static constexpr std::uint64_t kBase = 1000003;  // arithmetic modulo 2^64
  static std::uint64_t byte(char c) { return static_cast<unsigned char>(c); }
  std::uint64_t hash(const char* p) const {
    std::uint64_t h = 0;
    for (std::size_t k = 0; k < k_; ++k) h = h * kBase + byte(p[k]);
    return h;
  }
  const std::vector<std::string>& lines_;
  std::size_t k_ = 0;
  std::uint64_t top_ = 1;
  std::unordered_map<std::uint64_t, std::vector<std::size_t>> first_;
};

}  // namespace

bool is_secret_path(const fs::path& rel) {
  std::vector<std::string> parts;
  for (const auto& p : rel) parts.push_back(p.string());
  if (parts.empty()) return false;
  if (parts[0] == ".git" || (parts[0].rfind("build", 0) == 0 && parts[0] != "build.sh")) return true;
  if (parts[0] == "exercises" && parts.size() >= 2) {
    if (parts[1] == "_hostile" || parts[1] == "_template") return true;
    if (parts.size() >= 3 && (parts[2] == "solution" || parts[2] == "hidden" || parts[2] == "wrong")) return true;
    // The worked answers of the pen-and-paper questions (the questions are in README.md).
    if (parts.size() == 3 && parts[2] == "answers.md") return true;
  }
  if (parts[0] == "tests" && parts.size() == 2) {
    const std::string& f = parts[1];
    if (f.rfind("test_grader", 0) == 0 || f.rfind("test_exercises", 0) == 0) return true;
  }
  return false;
}

void copy_tree(const fs::path& src, const fs::path& out, bool for_students) {
  std::error_code ec;
  if (fs::exists(out, ec) && !fs::is_empty(out, ec))
    throw std::runtime_error(fmt::format("{} exists and is not empty: choose a new folder", out.string()));
  const fs::path s = fs::weakly_canonical(src), o = fs::weakly_canonical(out);
  const auto rel_out = o.lexically_relative(s);
  if (!rel_out.empty() && *rel_out.begin() != "..")
    throw std::runtime_error(fmt::format("{} is inside the source tree {}: choose a folder outside it", out.string(), src.string()));
  fs::create_directories(out);
  for (auto it = fs::recursive_directory_iterator(s, fs::directory_options::follow_directory_symlink); it != fs::recursive_directory_iterator(); ++it) {
    const fs::path rel = it->path().lexically_relative(s);
    const std::string top = rel.begin()->string();
    const bool skip = top == ".git" || (top.rfind("build", 0) == 0 && top != "build.sh") ||
                      (for_students && is_secret_path(rel));
    if (skip) {
      if (it->is_directory()) it.disable_recursion_pending();
      continue;
    }
    if (it->is_directory()) {
      fs::create_directories(out / rel);
    } else if (it->is_regular_file()) {
      fs::create_directories((out / rel).parent_path());
      fs::copy_file(it->path(), out / rel, fs::copy_options::overwrite_existing);
      fs::permissions(out / rel, fs::status(it->path()).permissions());
    }
  }
}

std::vector<std::string> secret_lines(const fs::path& source_root) {
  std::string pub;
  std::set<std::string> secret;
  const fs::path root = fs::weakly_canonical(source_root);
  std::error_code ec;
  for (auto it = fs::recursive_directory_iterator(root, fs::directory_options::follow_directory_symlink, ec); it != fs::recursive_directory_iterator(); it.increment(ec)) {
    const fs::path rel = it->path().lexically_relative(root);
    const std::string top = rel.begin()->string();
    if (top == ".git" || (top.rfind("build", 0) == 0 && top != "build.sh")) {
      if (it->is_directory()) it.disable_recursion_pending();
      continue;
    }
    if (!it->is_regular_file()) continue;
    const bool sec = is_secret_path(rel) && top == "exercises";
    if (!sec) {
      pub += slurp(it->path());
      pub += '\n';
      continue;
    }
    std::istringstream in(slurp(it->path()));
    std::string l;
    while (std::getline(in, l)) {
      l = trim(l);
      if (l.size() >= 30) secret.insert(l);
    }
  }
  const std::vector<std::string> lines(secret.begin(), secret.end());
  const std::vector<bool> in_pub = LineSet(lines).in(pub);
  std::vector<std::string> r;
  for (std::size_t i = 0; i < lines.size(); ++i)
    if (!in_pub[i]) r.push_back(lines[i]);
  return r;
}

std::vector<std::string> find_leaks(const fs::path& tree, const std::vector<std::string>& secrets) {
  std::vector<std::string> leaks;
  const LineSet search(secrets);
  for (const auto& f : files_under(tree)) {
    const std::vector<bool> found = search.in(slurp(f));
    for (std::size_t i = 0; i < secrets.size(); ++i) {
      if (found[i]) {
        leaks.push_back(fmt::format("{}: {}", f.lexically_relative(tree).string(), secrets[i]));
        if (leaks.size() > 50) return leaks;
      }
    }
  }
  return leaks;
}

}  // namespace t2grader
