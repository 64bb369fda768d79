#pragma once
// Helpers of the grader's own test suite (tests/test_grader.cpp, tests/test_exercises.cpp):
// run the `t2` tool (through the one process module), and read the results.json it writes.
#include <nlohmann/json.hpp>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "process.hpp"

namespace t2::grader_testing {

namespace fs = std::filesystem;

inline std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

/// Exit status and standard output of a shell command.
struct Ran {
  int status = -1;
  std::string out;
};
inline Ran run(const std::string& cmd) {
  t2proc::Spec s;
  s.argv = {"/bin/sh", "-c", cmd + " 2>&1"};
  const t2proc::Result r = t2proc::run(s);
  return {r.started && r.signal == 0 ? r.exit_code : -1, r.out};
}

/// A fresh temporary directory, removed at the end of the scope.
struct TempDir {
  fs::path path;
  TempDir() {
    std::string t = (fs::temp_directory_path() / "t2test-XXXXXX").string();
    if (!mkdtemp(t.data())) throw std::runtime_error("mkdtemp");
    path = t;
  }
  ~TempDir() {
    std::error_code ec;
    fs::remove_all(path, ec);
  }
};

/// One graded test of a results.json.
struct Graded {
  std::string name, output, visibility;
  double score = 0, max_score = 0;
};
/// A parsed results.json.
struct Results {
  double score = 0;
  std::string output, raw;
  std::vector<Graded> tests;
  const Graded* find(const std::string& n) const {
    for (const auto& t : tests)
      if (t.name == n) return &t;
    return nullptr;
  }
};

/// Runs `t2 grade` on a submission folder and reads its results.json.
inline Results grade(const std::string& tool, const std::string& exercise, const fs::path& submission,
                     const std::string& extra = "") {
  TempDir t;
  const fs::path res = t.path / "results.json";
  const Ran r = run("'" + tool + "' grade " + exercise + " --quiet --submission '" + submission.string() +
                    "' --results '" + res.string() + "' " + extra);
  if (r.status != 0) throw std::runtime_error("t2 grade failed (" + std::to_string(r.status) + "): " + r.out);
  Results out;
  out.raw = slurp(res);
  const auto j = nlohmann::json::parse(out.raw);  // throws on any syntax error
  out.score = j.at("score").get<double>();
  out.output = j.at("output").get<std::string>();
  for (const auto& t : j.at("tests"))
    out.tests.push_back({t.at("name").get<std::string>(), t.at("output").get<std::string>(),
                         t.at("visibility").get<std::string>(), t.at("score").get<double>(), t.at("max_score").get<double>()});
  return out;
}

/// found[i]: lines[i] occurs in `text` (as text.find(lines[i]) would say), for lines of at least
/// `window` characters, in one pass over the text: a line occurs only where its first `window`
/// characters do, so each window of the text is looked up among the lines' first windows and a
/// hit is confirmed by comparing the whole line. (One find per line read a 17 MB source tree
/// once per secret line: 250 s under the sanitizers.)
inline std::vector<bool> occur_in(const std::string& text, const std::vector<std::string>& lines,
                                  std::size_t window = 30) {
  std::unordered_multimap<std::string_view, std::size_t> first;
  for (std::size_t i = 0; i < lines.size(); ++i) {
    if (lines[i].size() < window) throw std::logic_error("occur_in: a line shorter than the window");
    first.emplace(std::string_view(lines[i]).substr(0, window), i);
  }
  std::vector<bool> found(lines.size(), false);
  const std::string_view t(text);
  for (std::size_t at = 0; at + window <= t.size(); ++at) {
    const auto [b, e] = first.equal_range(t.substr(at, window));
    for (auto it = b; it != e; ++it)
      if (!found[it->second] && t.substr(at).starts_with(lines[it->second])) found[it->second] = true;
  }
  return found;
}

/// The lines (of at least 30 characters) that do not occur in `text`, in their order.
inline std::vector<std::string> absent_from(const std::string& text, const std::vector<std::string>& lines) {
  const std::vector<bool> in = occur_in(text, lines);
  std::vector<std::string> r;
  for (std::size_t i = 0; i < lines.size(); ++i)
    if (!in[i]) r.push_back(lines[i]);
  return r;
}

}  // namespace t2::grader_testing
