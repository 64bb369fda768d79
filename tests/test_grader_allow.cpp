// The manifests' allow-lists (issue 29): what a submission's compile sees, read from the
// manifests and the library's headers, without running the grader.
#include <gtest/gtest.h>

#include <filesystem>
#include <map>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "../exercises/harness/grader_testing.hpp"

namespace {

namespace fs = std::filesystem;
using t2::grader_testing::slurp;

const fs::path kSource = T2_SOURCE_DIR;
const fs::path kExercises = kSource / "exercises";
const fs::path kInclude = kSource / "lib" / "include";

// The library headers a file includes by their full name ("t2/kernel/point.hpp").
std::set<std::string> includes(const fs::path& f) {
  static const std::regex inc(R"(^\s*#\s*include\s*[<"](t2/[^>"]+)[>"])");
  std::set<std::string> r;
  std::istringstream in(slurp(f));
  std::smatch m;
  for (std::string l; std::getline(in, l);)
    if (std::regex_search(l, m, inc)) r.insert(m[1].str());
  return r;
}

// The headers `allowed` brings in, transitively (as the grader's include view copies them).
std::set<std::string> closure(const std::set<std::string>& allowed) {
  std::set<std::string> seen;
  std::vector<std::string> todo(allowed.begin(), allowed.end());
  while (!todo.empty()) {
    const std::string h = todo.back();
    todo.pop_back();
    if (!seen.insert(h).second) continue;
    if (!fs::exists(kInclude / h)) continue;  // reported by the test below
    for (const auto& i : includes(kInclude / h)) todo.push_back(i);
  }
  return seen;
}

struct Manifest {
  fs::path dir;
  std::map<std::string, std::string> key;
  std::vector<std::string> list(const std::string& k) const {
    std::vector<std::string> r;
    const auto it = key.find(k);
    if (it == key.end()) return r;
    std::istringstream names(it->second);
    for (std::string n; std::getline(names, n, ',');)
      if (const auto b = n.find_first_not_of(' '); b != std::string::npos) r.push_back(n.substr(b, n.find_last_not_of(' ') + 1 - b));
    return r;
  }
};

std::vector<Manifest> manifests() {
  std::vector<Manifest> r;
  for (const auto& e : fs::directory_iterator(kExercises)) {
    if (!fs::exists(e.path() / "exercise.txt") || e.path().filename().string()[0] == '_') continue;
    Manifest m{e.path(), {}};
    std::istringstream in(slurp(e.path() / "exercise.txt"));
    for (std::string l; std::getline(in, l);)
      if (const auto c = l.find(':'); c != std::string::npos && l[0] != '#') m.key[l.substr(0, c)] += l.substr(c + 1);
    r.push_back(m);
  }
  return r;
}

// A header's text without its comments: a name in a comment defines nothing. Each header is
// read once (the manifests share most of their headers: std::regex_replace over the same
// headers for each of 31 manifests took most of the test's 42 s under the sanitizers).
const std::string& code_of(const fs::path& f) {
  static const std::regex comments(R"(//[^\n]*|/\*[\s\S]*?\*/)");
  static std::map<fs::path, std::string> done;
  auto it = done.find(f);
  if (it == done.end()) it = done.emplace(f, std::regex_replace(slurp(f), comments, " ")).first;
  return it->second;
}

}  // namespace

// `allowed:` names every library header that the API header, the stub, the reference and the
// wrong solutions include, and what those headers include, transitively, is the kernel only (no
// algorithm header, whose code a macro could rename).
TEST(GraderAllowList, EveryManifestAllowsWhatItsCodeIncludesAndOnlyKernelHeaders) {
  const auto all = manifests();
  for (const auto& m : all) {
    ASSERT_TRUE(m.key.count("allowed")) << m.dir;
    const auto names = m.list("allowed");
    const std::set<std::string> allowed(names.begin(), names.end());
    const std::string source = m.list("source").at(0), header = m.list("header").at(0);
    std::vector<fs::path> code = {m.dir / source, m.dir / header, m.dir / "solution" / source};
    for (const auto& w : fs::directory_iterator(m.dir / "wrong")) code.push_back(w.path() / source);
    for (const auto& f : code)
      for (const auto& h : includes(f)) EXPECT_TRUE(allowed.count(h)) << f << " includes " << h << ", not in allowed:";
    for (const auto& h : closure(allowed)) {
      EXPECT_EQ(h.rfind("t2/kernel/", 0), 0u) << m.dir.filename() << " allows " << h << " (through its includes)";
      EXPECT_TRUE(fs::exists(kInclude / h)) << h;
    }
  }
  EXPECT_GE(all.size(), 20u);
}

// The allow-list is the wall, the symbol check the second one: no header a submission may see
// declares a name its exercise forbids (a function, an operator, a class or alias, a namespace).
// Exercise 01 forbids t2::antipode and t2::operator==, 02b t2::mix, 04 t2::sign_of_poly and
// t2::expansion: all in point.hpp or what it includes, which is why those exercises allow
// point_type.hpp (the type without its operations) instead.
TEST(GraderAllowList, NoAllowedHeaderDeclaresAForbiddenName) {
  int checked = 0;
  for (const auto& m : manifests()) {
    const auto names = m.list("allowed");
    std::map<std::string, std::string> text;  // header -> code without comments
    for (const auto& h : closure({names.begin(), names.end()})) text[h] = code_of(kInclude / h);
    for (const auto& f : m.list("forbidden")) {
      if (f.rfind("t2::", 0) != 0) continue;  // GMP's and the compiler runtime's names: not in t2's headers
      const std::string last = f.substr(f.rfind("::") + 2);
      std::string pattern;
      if (last.rfind("operator", 0) == 0)
        pattern = std::regex_replace(last, std::regex(R"([^\w])"), R"(\$&)") + R"(\s*[(<])";
      else
        pattern = R"(\b)" + last + R"(\s*[(<]|(class|struct|using|namespace)\s+)" + last + R"(\b)";
      const std::regex declares(pattern);
      for (const auto& [h, code] : text) {
        ++checked;
        // Every match of `declares` holds `last` as written: a header without it declares nothing
        // of that name (the regular expression is searched only where it could match).
        if (code.find(last) == std::string::npos) continue;
        EXPECT_FALSE(std::regex_search(code, declares)) << m.dir.filename().string() << " forbids " << f << ", which its allowed " << h << " declares";
      }
    }
  }
  EXPECT_GT(checked, 100);
}
