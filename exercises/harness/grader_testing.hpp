#pragma once
// Helpers of the grader's own test suite (tests/test_grader.cpp, tests/test_exercises.cpp):
// run the `t2` tool, and read the results.json it writes with a small strict JSON parser.
#include <sys/wait.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <string>
#include <variant>
#include <vector>

namespace t2::grader_testing {

namespace fs = std::filesystem;

/// A JSON value (strict parser: throws std::runtime_error on any syntax error).
struct Json {
  std::variant<std::nullptr_t, bool, double, std::string, std::vector<Json>, std::map<std::string, Json>> v;
  const Json& operator[](const std::string& k) const { return std::get<std::map<std::string, Json>>(v).at(k); }
  const std::vector<Json>& array() const { return std::get<std::vector<Json>>(v); }
  const std::string& str() const { return std::get<std::string>(v); }
  double num() const { return std::get<double>(v); }
  bool has(const std::string& k) const {
    const auto* m = std::get_if<std::map<std::string, Json>>(&v);
    return m && m->count(k);
  }
};

class JsonParser {
 public:
  explicit JsonParser(std::string s) : s_(std::move(s)) {}
  Json parse() {
    Json j = value();
    ws();
    if (i_ != s_.size()) fail("trailing characters");
    return j;
  }

 private:
  std::string s_;
  size_t i_ = 0;
  [[noreturn]] void fail(const std::string& m) { throw std::runtime_error("JSON: " + m + " at " + std::to_string(i_)); }
  void ws() {
    while (i_ < s_.size() && (s_[i_] == ' ' || s_[i_] == '\n' || s_[i_] == '\t' || s_[i_] == '\r')) ++i_;
  }
  bool eat(char c) {
    ws();
    if (i_ < s_.size() && s_[i_] == c) {
      ++i_;
      return true;
    }
    return false;
  }
  std::string string() {
    if (!eat('"')) fail("expected a string");
    std::string r;
    while (i_ < s_.size() && s_[i_] != '"') {
      char c = s_[i_++];
      if (static_cast<unsigned char>(c) < 0x20) fail("control character in a string");
      if (c == '\\') {
        if (i_ >= s_.size()) fail("bad escape");
        const char e = s_[i_++];
        if (e == 'n') r += '\n';
        else if (e == 't') r += '\t';
        else if (e == 'r') r += '\r';
        else if (e == '"' || e == '\\' || e == '/') r += e;
        else if (e == 'u') {
          if (i_ + 4 > s_.size()) fail("bad \\u");
          r += static_cast<char>(std::stoi(s_.substr(i_, 4), nullptr, 16));
          i_ += 4;
        } else fail("bad escape");
      } else {
        r += c;
      }
    }
    if (i_ >= s_.size()) fail("unterminated string");
    ++i_;
    return r;
  }
  Json value() {
    ws();
    if (i_ >= s_.size()) fail("unexpected end");
    const char c = s_[i_];
    if (c == '"') return Json{string()};
    if (c == '{') {
      ++i_;
      std::map<std::string, Json> m;
      if (eat('}')) return Json{m};
      do {
        std::string k = string();
        if (!eat(':')) fail("expected ':'");
        m[k] = value();
      } while (eat(','));
      if (!eat('}')) fail("expected '}'");
      return Json{m};
    }
    if (c == '[') {
      ++i_;
      std::vector<Json> a;
      if (eat(']')) return Json{a};
      do a.push_back(value());
      while (eat(','));
      if (!eat(']')) fail("expected ']'");
      return Json{a};
    }
    if (s_.compare(i_, 4, "true") == 0) { i_ += 4; return Json{true}; }
    if (s_.compare(i_, 5, "false") == 0) { i_ += 5; return Json{false}; }
    if (s_.compare(i_, 4, "null") == 0) { i_ += 4; return Json{nullptr}; }
    size_t n = 0;
    const double d = std::stod(s_.substr(i_), &n);
    if (n == 0) fail("bad value");
    i_ += n;
    return Json{d};
  }
};

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
  Ran r;
  FILE* f = popen((cmd + " 2>&1").c_str(), "r");
  if (!f) return r;
  char buf[4096];
  size_t n;
  while ((n = fread(buf, 1, sizeof buf, f)) > 0) r.out.append(buf, n);
  const int st = pclose(f);
  r.status = WIFEXITED(st) ? WEXITSTATUS(st) : -1;
  return r;
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
  const Json j = JsonParser(out.raw).parse();
  out.score = j["score"].num();
  out.output = j["output"].str();
  for (const auto& t : j["tests"].array())
    out.tests.push_back({t["name"].str(), t["output"].str(), t["visibility"].str(), t["score"].num(),
                         t["max_score"].num()});
  return out;
}

}  // namespace t2::grader_testing
