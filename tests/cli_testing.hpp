#pragma once
// Tests of the `t2` command line: each test gets its own folder, runs the built tool there
// (T2_TOOL, through t2proc) and sees its exit status, stdout, stderr and the files it leaves
// behind. Also: whether an optional program (pandoc, chromium) is installed, for tests that skip.
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <string_view>
#include <vector>

#include "process.hpp"
#include "t2/kernel/io.hpp"

namespace t2::testing {

namespace fs = std::filesystem;

/// What a run of the tool gave.
struct Result {
  int status = -1;
  std::string out, err;
};

/// The whole content of a file ("" if it does not exist).
inline std::string slurp(const fs::path& p) {
  std::error_code ec;
  return fs::exists(p, ec) ? t2::read_file(p) : std::string();
}

/// True when `name` is an executable file in a folder of PATH. A test that needs an optional
/// program skips without it: if (!have_program("pandoc")) GTEST_SKIP() << "...";
inline bool have_program(const std::string& name) {
  const char* path = std::getenv("PATH");
  std::string_view dirs = path ? path : "/usr/bin:/bin";
  while (!dirs.empty()) {
    const auto colon = dirs.find(':');
    const fs::path dir(std::string(dirs.substr(0, colon)));
    if (!dir.empty() && ::access((dir / name).c_str(), X_OK) == 0) return true;
    dirs = colon == std::string_view::npos ? std::string_view() : dirs.substr(colon + 1);
  }
  return false;
}

/// Skips the current test when pandoc is missing (the book tests need it).
#define T2_NEEDS_PANDOC()                                     \
  if (!::t2::testing::have_program("pandoc"))                 \
  GTEST_SKIP() << "pandoc is not installed (the Debian package pandoc): skipped"

/// A shell command line run through t2proc (no shell of our own, no popen): its exit status
/// (-1 when killed by a signal or not started) and stdout; stderr too with `with_stderr`
/// ("2>&1", in the order written).
struct Shell {
  int status = -1;
  std::string out;
};
inline Shell shell(const std::string& command, const fs::path& cwd = {}, const std::string& input = "",
                   bool with_stderr = true) {
  t2proc::Spec s;
  s.argv = {"/bin/sh", "-c", with_stderr ? "exec 2>&1; " + command : command};
  s.cwd = cwd;
  s.stdin_data = input;
  s.err = t2proc::Stream::inherit;
  const t2proc::Result r = t2proc::run(s);
  return {r.started && r.signal == 0 ? r.exit_code : -1, r.out};
}

inline bool has(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

class CliTest : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ = fs::temp_directory_path() / ("t2_cli_" + std::to_string(::getpid()) + "_" +
                                        info->test_suite_name() + "_" + info->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  // Writes `text` to the file `name` of the test folder, making its folders.
  fs::path write(const std::string& name, const std::string& text) {
    const fs::path p = dir_ / name;
    fs::create_directories(p.parent_path());
    std::ofstream(p, std::ios::binary) << text;
    return p;
  }

  // Runs `t2 <args>` in the test folder with `input` on stdin (args are split by the shell, so
  // they may quote); files() lists only what the tool wrote.
  Result t2(const std::string& args, const std::string& input = "") {
    t2proc::Spec s;
    s.argv = {"/bin/sh", "-c", "exec '" + std::string(T2_TOOL) + "' " + args};
    s.cwd = dir_;
    s.stdin_data = input;
    const t2proc::Result p = t2proc::run(s);
    Result r;
    r.status = p.started && p.signal == 0 ? p.exit_code : -1;
    r.out = p.out;
    r.err = p.err;
    return r;
  }

  // The files of the test folder, sorted.
  std::vector<std::string> files() const {
    std::vector<std::string> names;
    for (const auto& e : fs::directory_iterator(dir_)) names.push_back(e.path().filename().string());
    std::sort(names.begin(), names.end());
    return names;
  }

  fs::path dir_;
};

}  // namespace t2::testing
