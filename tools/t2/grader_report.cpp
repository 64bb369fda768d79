// Reports of a grading run: Gradescope's results.json (nlohmann-json), the summary of `t2 grade`
// and the plain-words report of `t2 check`. See grader_core.hpp.
#include <sstream>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "grader_core.hpp"

namespace t2grader {

namespace {
std::string num(double v) { return fmt::format("{}", v); }
}  // namespace

std::string results_json(const Report& r, const std::string& hidden_visibility) {
  nlohmann::ordered_json j;
  j["score"] = r.score();
  std::string top = fmt::format("{}: {} of {} points. Protection: {}.", r.exercise.title, num(r.score()),
                                num(r.max_score()), r.protection);
  if (!r.compiled) top += "\nYour code was not run:\n" + r.compiler_output;
  if (r.overall_timeout) top += "\nThe grading run hit its overall time limit.";
  j["output"] = top;
  j["tests"] = nlohmann::ordered_json::array();
  for (const auto& t : r.tests) {
    std::string o = t.what;
    if (!t.hidden && !t.detail.empty()) o += "\n" + t.detail;
    j["tests"].push_back({{"name", t.name},
                          {"score", t.passed ? t.max_score : 0.0},
                          {"max_score", t.max_score},
                          {"output", o},
                          {"visibility", t.hidden ? hidden_visibility : "visible"}});
  }
  // Student text (exception messages) may be any bytes: replace what is not UTF-8.
  return j.dump(2, ' ', false, nlohmann::json::error_handler_t::replace) + "\n";
}

std::string grade_summary(const Report& r) {
  std::string s = fmt::format("{} ({})\n", r.exercise.title, r.exercise.id);
  if (!r.compiled) s += "not run (score 0):\n" + r.compiler_output + "\n";
  for (const auto& t : r.tests)
    s += fmt::format("  {:<4} {:<45} {:>4}/{:<4} {}\n", t.passed ? "ok" : "FAIL", t.name + (t.hidden ? " (hidden)" : ""),
                     num(t.passed ? t.max_score : 0), num(t.max_score), t.what);
  s += fmt::format("score: {} of {}\nprotection: {}\n", num(r.score()), num(r.max_score()), r.protection);
  if (r.overall_timeout) s += "the overall time limit stopped the run\n";
  return s;
}

std::string check_summary(const Report& r) {
  std::string s = fmt::format("Exercise {}: {}\n\n", r.exercise.id, r.exercise.title);
  if (!r.compiled) {
    s += "Your code was not run. " + std::string(r.compiler_output.find("error") != std::string::npos
                                                     ? "The compiler says:\n\n"
                                                     : "Why:\n\n") +
         r.compiler_output + "\nFix the first error first: the others often follow from it.\n";
    return s;
  }
  int passed = 0;
  for (const auto& t : r.tests) {
    if (t.passed) {
      ++passed;
      s += fmt::format("  passed  {}\n", t.name);
    } else {
      s += fmt::format("  FAILED  {}: {}\n", t.name, t.what);
      std::istringstream in(t.detail);
      std::string line;
      for (int n = 0; std::getline(in, line) && n < 12; ++n) s += "          " + line + "\n";
    }
  }
  s += fmt::format("\n{} of {} public tests pass; score so far {} of {} public points.\n", passed, r.tests.size(),
                   num(r.score()), num(r.max_score()));
  if (passed == static_cast<int>(r.tests.size()))
    s += "Next: the hidden tests try more of T2 (back side, points at infinity, antipodes, degenerate "
         "input). Think about each of those cases before you submit.\n";
  else
    s += "Next: fix the first failing test above, read its hint, and run `t2 check " + r.exercise.id + "` again.\n";
  return s;
}

}  // namespace t2grader
