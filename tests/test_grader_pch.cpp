// The grader's precompiled header (issue 23): the sandboxed compile of a submission takes the
// exercise's allowed headers from one precompiled header that the grader made and cached, and
// that changes nothing a submission can tell: the allowed headers are still read before its
// first line.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "../exercises/harness/grader_testing.hpp"

namespace {

namespace fs = std::filesystem;
using namespace t2::grader_testing;

const std::string kTool = T2_TOOL;
const fs::path kExercises = fs::path(T2_SOURCE_DIR) / "exercises";
const fs::path kCache = fs::path(T2_BINARY_DIR) / "grader-cache";

// `t2 grade 12b` on a submission folder holding `tree_cpp`: the tool's output (stdout and
// stderr) and the parsed results.json.
struct Graded12b {
  Ran ran;
  nlohmann::json results;
};
Graded12b grade_12b(const std::string& tree_cpp) {
  TempDir t;
  fs::create_directories(t.path / "sub");
  std::ofstream(t.path / "sub" / "tree.cpp") << tree_cpp;
  const fs::path res = t.path / "results.json";
  Graded12b g;
  g.ran = run("'" + kTool + "' grade 12b --quiet --submission '" + (t.path / "sub").string() + "' --results '" +
              res.string() + "'");
  if (fs::exists(res)) g.results = nlohmann::json::parse(slurp(res));
  return g;
}

std::string ascii_quotes(std::string s) {  // GCC quotes with ‘ ’ or ' ' depending on the locale
  for (const std::string q : {"\u2018", "\u2019"})
    for (size_t at; (at = s.find(q)) != std::string::npos;) s.replace(at, q.size(), "'");
  return s;
}

}  // namespace

// The reference solution of 12b scores full marks, and its compile in the sandbox read no file
// of the include view as text (the grader reads the compiler's dependency list and warns when
// it did: a missing or unusable .gch, or the allowed headers passed one by one again). The
// precompiled header is in the cache, verified by its SHA-256 like every cached file.
TEST(GraderPch, TheSandboxedCompileTakesTheAllowedHeadersPrecompiled) {
  const Graded12b g = grade_12b(slurp(kExercises / "12b-spanning-tree" / "solution" / "tree.cpp"));
  ASSERT_EQ(g.ran.status, 0) << g.ran.out;
  EXPECT_EQ(g.ran.out.find("did not use the precompiled"), std::string::npos) << g.ran.out;
  double max = 0;
  for (const auto& t : g.results.at("tests")) max += t.at("max_score").get<double>();
  EXPECT_GT(max, 0);
  EXPECT_EQ(g.results.at("score").get<double>(), max) << g.results.dump(2);
  int headers = 0;
  for (const auto& e : fs::directory_iterator(kCache)) {
    const std::string name = e.path().filename().string();
    if (name.rfind("allowed.gch-", 0) != 0 || name.find(".tmp") != std::string::npos || e.path().extension() == ".sha256")
      continue;
    ++headers;
    EXPECT_GT(fs::file_size(e.path()), 1u << 20) << name;
    const Ran sum = run("sha256sum '" + e.path().string() + "'");
    EXPECT_EQ(sum.out.substr(0, 64), slurp(e.path().string() + ".sha256")) << name;
  }
  EXPECT_GE(headers, 1) << "no precompiled header in " << kCache;
}

// A macro defined before the submission includes an allowed header does not rename what the
// header declares (issue 29, break 1): the precompiled header was read first, so the #include is
// empty (#pragma once) and t2::renamed_orient does not exist. The same file compiled as a
// plain program (its #include first) does compile: the macro would rename t2::orient.
TEST(GraderPch, AMacroBeforeAnAllowedHeaderRenamesNothing) {
  const std::string code = R"(#define orient renamed_orient
#include <t2/kernel/orient.hpp>
#include "tree.hpp"
int t2_renamed(const t2::Point& p) { return static_cast<int>(t2::renamed_orient(p, p, p)); }
)";
  TempDir t;
  std::ofstream(t.path / "tree.cpp") << code;
  const Ran plain = run("g++ -std=c++20 -fsyntax-only -I '" + (fs::path(T2_SOURCE_DIR) / "lib" / "include").string() +
                        "' -I '" + (kExercises / "12b-spanning-tree").string() + "' '" + (t.path / "tree.cpp").string() + "'");
  ASSERT_EQ(plain.status, 0) << "without the allowed headers first, the macro renames t2::orient: " << plain.out;
  const Graded12b g = grade_12b(code);
  ASSERT_EQ(g.ran.status, 0) << g.ran.out;
  EXPECT_EQ(g.results.at("score").get<double>(), 0);
  const std::string out = ascii_quotes(g.results.at("output").get<std::string>());
  EXPECT_NE(out.find("'renamed_orient' is not a member of 't2'"), std::string::npos) << out;
}
