// What a submission's compile sees: see grader_allow.hpp.
#include "grader_allow.hpp"

#include <algorithm>
#include <fstream>
#include <optional>
#include <regex>
#include <set>
#include <sstream>

#include <fmt/format.h>

#include "grader_cache.hpp"
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

// The entries of /usr/include the compiler reads for the whole standard library and the allowed
// headers (the trusted compiler, outside the sandbox, on a file of ours), one a line.
std::string system_entries(const Exercise& ex, const fs::path& tree, const fs::path& work) {
  const fs::path probe = work / "allowed-headers.cpp";
  {
    std::ofstream o(probe);
    o << "#include <bits/stdc++.h>\n";
    for (const auto& h : ex.allowed) o << "#include <" << h << ">\n";
  }
  t2proc::Spec s;
  s.argv = {"g++", "-std=c++20", "-M", "-I", tree.string(), probe.string()};
  s.limits.wall_seconds = 120;
  s.limits.output_bytes = 4u << 20;
  const t2proc::Result r = t2proc::run(s);
  if (!r.ok()) throw GraderError(fmt::format("internal error: the allowed headers of {} do not compile:\n{}{}", ex.id, r.error, r.err));
  std::set<fs::path> entries;
  std::istringstream deps(r.out);
  for (std::string w; deps >> w;)
    if (const auto e = system_entry(w)) entries.insert(*e);
  std::string lines;
  for (const auto& e : entries) lines += e.string() + "\n";
  return lines;
}

}  // namespace

IncludeView include_view(const Exercise& ex, const fs::path& work, std::uint64_t toolchain) {
  IncludeView v;
  v.tree = work / "include";
  v.headers = header_closure(library_include_dir(), ex.allowed);
  for (const auto& h : v.headers) {
    fs::create_directories((v.tree / h).parent_path());
    fs::copy_file(library_include_dir() / h, v.tree / h, fs::copy_options::overwrite_existing);
  }
  if (!ex.allowed.empty()) {
    // One header for the allowed ones, in the manifest's order, by the paths the compile sees:
    // the first -include, which GCC may take from a precompiled header beside it.
    std::ofstream o(v.tree / kAllowedHeader);
    o << "// The headers this exercise allows, read before the submission (t2 grade).\n#pragma once\n";
    for (const auto& h : ex.allowed) o << "#include \"/t2/include/" << h << "\"\n";
  }
  fs::permissions(work / "include", fs::perms::owner_all | fs::perms::group_read | fs::perms::group_exec |
                                        fs::perms::others_read | fs::perms::others_exec);
  // The system headers, cached per toolchain and allow-list (the compiler's -M takes 0.12-0.2 s).
  std::string key;
  for (const auto& h : ex.allowed) key += h + "\n";
  const fs::path list = cached(work, "system-headers.txt", fnv1a(key, toolchain),
                               [&](const fs::path& tmp) { std::ofstream(tmp) << system_entries(ex, v.tree, work); });
  std::istringstream entries(read_text(list));
  for (std::string e; std::getline(entries, e);)
    if (system_entry(e) == fs::path(e)) v.system.push_back(e);
  if (v.system.empty()) throw GraderError("internal error: no system header in " + list.string());
  for (const char* d : {"/usr/include", "/usr/local/include"}) {
    std::error_code ec;
    if (fs::is_directory(d, ec) && !fs::is_symlink(d, ec)) v.masked.push_back(d);
  }
  return v;
}

}  // namespace t2grader
