// Exercises and their manifests: see grader_core.hpp.
#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <sstream>

#include <fmt/format.h>

#include "grader_core.hpp"
#include "t2/kernel/error.hpp"

#ifndef T2_SOURCE_DIR
#define T2_SOURCE_DIR "."
#endif

namespace t2grader {

namespace {

std::string trim(const std::string& s) {
  const auto b = s.find_first_not_of(" \t\r\n");
  if (b == std::string::npos) return {};
  return s.substr(b, s.find_last_not_of(" \t\r\n") - b + 1);
}

}  // namespace

double Exercise::points_of(const std::string& test) const {
  const auto it = points.find(test);
  return it == points.end() ? 1.0 : it->second;
}

fs::path exercises_root(const std::optional<std::string>& override_dir) {
  if (override_dir) return *override_dir;
  if (const char* e = std::getenv("T2_EXERCISES_DIR"); e && *e) return e;
  return fs::path(T2_SOURCE_DIR) / "exercises";
}

Exercise read_exercise(const fs::path& dir) {
  Exercise ex;
  ex.dir = fs::absolute(dir).lexically_normal();
  if (ex.dir.filename().empty()) ex.dir = ex.dir.parent_path();
  ex.id = ex.dir.filename().string();
  const fs::path m = ex.dir / "exercise.txt";
  std::ifstream in(m);
  if (!in) throw t2::BadInput(fmt::format("{}: cannot read the manifest", m.string()));
  std::string line;
  bool forbidden_line = false, allowed_line = false;
  for (int n = 1; std::getline(in, line); ++n) {
    line = trim(line);
    if (line.empty() || line[0] == '#') continue;
    const auto colon = line.find(':');
    if (colon == std::string::npos)
      throw t2::BadInput(fmt::format("{}:{}: expected 'key: value'", m.string(), n));
    const std::string k = trim(line.substr(0, colon)), v = trim(line.substr(colon + 1));
    auto number = [&](const std::string& s) {
      char* end = nullptr;
      const double d = std::strtod(s.c_str(), &end);
      if (s.empty() || *end || !(d > 0) || d > 1e6)
        throw t2::BadInput(fmt::format("{}:{}: '{}' is not a positive number", m.string(), n, s));
      return d;
    };
    if (k == "title") ex.title = v;
    else if (k == "chapter") ex.chapter = v;
    else if (k == "header") ex.header = v;
    else if (k == "source") ex.source = v;
    else if (k == "time_limit") ex.time_limit = static_cast<int>(number(v));
    else if (k == "memory_mb") ex.memory_mb = static_cast<int>(number(v));
    else if (k == "forbidden") {
      // Qualified names separated by commas: t2::antipode, t2::operator==, t2::Polygon
      forbidden_line = true;
      std::istringstream names(v);
      for (std::string f; std::getline(names, f, ',');)
        if (!trim(f).empty()) ex.forbidden.push_back(trim(f));
    } else if (k == "allowed") {
      // Library headers separated by commas: t2/kernel/point.hpp, t2/kernel/filter.hpp
      allowed_line = true;
      std::istringstream names(v);
      for (std::string f; std::getline(names, f, ',');) {
        f = trim(f);
        if (f.empty()) continue;
        if (f.rfind("t2/", 0) != 0 || f.find("..") != std::string::npos || f.size() < 5 || f.substr(f.size() - 4) != ".hpp")
          throw t2::BadInput(fmt::format("{}:{}: '{}' is not a library header (t2/.../NAME.hpp)", m.string(), n, f));
        ex.allowed.push_back(f);
      }
    } else if (k == "points") {
      const auto sp = v.find_last_of(" \t");
      if (sp == std::string::npos)
        throw t2::BadInput(fmt::format("{}:{}: expected 'points: Suite.Test N'", m.string(), n));
      ex.points[trim(v.substr(0, sp))] = number(trim(v.substr(sp + 1)));
    } else {
      throw t2::BadInput(fmt::format("{}:{}: unknown key '{}'", m.string(), n, k));
    }
  }
  for (auto [key, val] : {std::pair{"title", &ex.title}, {"header", &ex.header}, {"source", &ex.source}})
    if (val->empty()) throw t2::BadInput(fmt::format("{}: missing '{}:'", m.string(), key));
  if (!forbidden_line)
    throw t2::BadInput(fmt::format("{}: missing 'forbidden:' (the library names the exercise must not call)", m.string()));
  if (!allowed_line)
    throw t2::BadInput(fmt::format("{}: missing 'allowed:' (the library headers a submission may include)", m.string()));
  return ex;
}

std::vector<Exercise> all_exercises(const fs::path& root) {
  std::vector<Exercise> r;
  std::error_code ec;
  std::vector<fs::path> dirs;
  for (const auto& e : fs::directory_iterator(root, ec))
    if (e.is_directory() && fs::exists(e.path() / "exercise.txt") && e.path().filename().string()[0] != '_')
      dirs.push_back(e.path());
  std::sort(dirs.begin(), dirs.end());
  for (const auto& d : dirs) r.push_back(read_exercise(d));
  return r;
}

Exercise find_exercise(const fs::path& root, const std::string& name) {
  std::error_code ec;
  if (name.find('/') != std::string::npos && fs::exists(fs::path(name) / "exercise.txt", ec))
    return read_exercise(name);
  const auto all = all_exercises(root);
  for (const auto& e : all)
    if (e.id == name || e.id.rfind(name + "-", 0) == 0) return e;
  std::string known;
  for (const auto& e : all) known += " " + e.id;
  throw GraderError(fmt::format("no exercise '{}' in {} (there are:{})", name, root.string(),
                                known.empty() ? " none" : known));
}

}  // namespace t2grader
