#pragma once
// Tests of the `t2` command line: each test gets its own folder, runs the built tool there
// (T2_TOOL) and sees its exit status, stdout, stderr and the files it leaves behind.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace t2::testing {

namespace fs = std::filesystem;

/// What a run of the tool gave.
struct Result {
  int status = -1;
  std::string out, err;
};

/// The whole content of a file ("" if it does not exist).
inline std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
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

  fs::path write(const std::string& name, const std::string& text) {
    const fs::path p = dir_ / name;
    std::ofstream(p, std::ios::binary) << text;
    return p;
  }

  // Runs `t2 <args>` in the test folder with `input` on stdin; the capture files are removed
  // afterwards, so files() lists only what the tool wrote.
  Result t2(const std::string& args, const std::string& input = "") {
    write(".stdin", input);
    const std::string cmd = "cd '" + dir_.string() + "' && '" + std::string(T2_TOOL) + "' " + args +
                            " <.stdin >.stdout 2>.stderr";
    const int raw = std::system(cmd.c_str());
    Result r;
    r.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
    r.out = slurp(dir_ / ".stdout");
    r.err = slurp(dir_ / ".stderr");
    for (const char* f : {".stdin", ".stdout", ".stderr"}) fs::remove(dir_ / f);
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
