// What a submission's compile sees: see grader_allow.hpp.
#include "grader_allow.hpp"

#include <algorithm>
#include <fstream>
#include <optional>
#include <regex>
#include <set>
#include <sstream>

#include <fmt/format.h>

#include "process.hpp"

#ifndef T2_SOURCE_DIR
#define T2_SOURCE_DIR "."
#endif

namespace t2grader {

fs::path library_include_dir() { return fs::path(T2_SOURCE_DIR) / "lib" / "include"; }

std::vector<std::string> header_closure(const fs::path& include_root, const std::vector<std::string>& allowed) {
  // The library includes its own headers by their full name ("t2/kernel/filter.hpp"), in quotes
  // or angle brackets; a conditional #include is followed all the same (the view may be larger
  // than a compile needs, never smaller).
  static const std::regex inc(R"(^\s*#\s*include\s*[<"](t2/[^>"]+)[>"])");
  std::set<std::string> seen;
  std::vector<std::string> todo(allowed.begin(), allowed.end());
  while (!todo.empty()) {
    const std::string h = todo.back();
    todo.pop_back();
    if (!seen.insert(h).second) continue;
    std::ifstream in(include_root / h);
    if (!in) throw GraderError(fmt::format("the allowed header {} is not in {}", h, include_root.string()));
    std::smatch m;
    for (std::string line; std::getline(in, line);)
      if (std::regex_search(line, m, inc)) todo.push_back(m[1].str());
  }
  return {seen.begin(), seen.end()};
}

namespace {

// The entry of /usr/include to bind back for one header the compiler read: the file itself when
// it sits at the top of /usr/include or of a multiarch folder (x86_64-linux-gnu), else the folder
// at that level that holds it (c++/, bits/, linux/ ...).
std::optional<fs::path> system_entry(const std::string& header) {
  const fs::path usr_include = "/usr/include";
  const fs::path rel = fs::path(header).lexically_normal().lexically_relative(usr_include);
  if (rel.empty() || *rel.begin() == "..") return std::nullopt;
  fs::path base = usr_include;
  auto it = rel.begin();
  if (it->string().find("-linux-") != std::string::npos) base /= *it++;
  if (it == rel.end()) return std::nullopt;
  const fs::path first = *it;
  return base / first;
}

}  // namespace

IncludeView include_view(const Exercise& ex, const fs::path& work) {
  IncludeView v;
  v.tree = work / "include";
  v.headers = header_closure(library_include_dir(), ex.allowed);
  for (const auto& h : v.headers) {
    fs::create_directories((v.tree / h).parent_path());
    fs::copy_file(library_include_dir() / h, v.tree / h, fs::copy_options::overwrite_existing);
  }
  fs::permissions(work / "include", fs::perms::owner_all | fs::perms::group_read | fs::perms::group_exec |
                                        fs::perms::others_read | fs::perms::others_exec);
  // The system headers: whatever the compiler reads for the whole standard library and the
  // allowed headers (the trusted compiler, outside the sandbox, on a file of ours).
  const fs::path probe = work / "allowed-headers.cpp";
  {
    std::ofstream o(probe);
    o << "#include <bits/stdc++.h>\n";
    for (const auto& h : ex.allowed) o << "#include <" << h << ">\n";
  }
  t2proc::Spec s;
  s.argv = {"g++", "-std=c++20", "-M", "-I", v.tree.string(), probe.string()};
  s.limits.wall_seconds = 120;
  s.limits.output_bytes = 4u << 20;
  const t2proc::Result r = t2proc::run(s);
  if (!r.ok()) throw GraderError(fmt::format("internal error: the allowed headers of {} do not compile:\n{}{}", ex.id, r.error, r.err));
  std::set<fs::path> entries;
  std::istringstream deps(r.out);
  for (std::string w; deps >> w;)
    if (const auto e = system_entry(w)) entries.insert(*e);
  v.system.assign(entries.begin(), entries.end());
  for (const char* d : {"/usr/include", "/usr/local/include"}) {
    std::error_code ec;
    if (fs::is_directory(d, ec) && !fs::is_symlink(d, ec)) v.masked.push_back(d);
  }
  return v;
}

}  // namespace t2grader
