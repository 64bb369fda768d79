// The main() of the checker: the exercise's tests (public or hidden) with their oracles, linked
// with the exercise's remote.cpp in place of the student's code. It never links student code:
// each call of the exercise's API travels to the sandboxed driver (judge_wire.hpp) and only the
// answer comes back. The verdict is decided here, in a trusted process, and written on stdout:
//   PASS | FAIL | GONE (the driver stopped answering) | LIMIT (an answer too long), then the
//   failure messages (shown for public tests only).
// Usage: checker --t2-calls=FD --t2-answers=FD --gtest_filter=Suite.Name
//        checker --t2-list            (the names of the tests, one per line)
#include <gtest/gtest.h>
#include <signal.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>

#include "judge_wire.hpp"

namespace t2judge {

Channel& channel() {
  static Channel c;
  return c;
}

namespace {
constexpr size_t kAnswerLimit = 8u << 20;  // bytes of one answer line
}  // namespace

std::string exchange(const std::string& line) {
  Channel& c = channel();
  if (c.gone || !t2judge::write_all(c.calls, line)) {
    c.gone = true;
    throw DriverGone();
  }
  static std::string pending;  // bytes read past the previous answer
  for (;;) {
    const auto nl = pending.find('\n');
    if (nl != std::string::npos) {
      std::string answer = pending.substr(0, nl);
      pending.erase(0, nl + 1);
      return answer;
    }
    if (pending.size() > kAnswerLimit) {
      c.gone = c.too_long = true;
      throw DriverGone();
    }
    char buf[65536];
    const ssize_t n = ::read(c.answers, buf, sizeof buf);
    if (n <= 0) {
      c.gone = true;
      throw DriverGone();
    }
    pending.append(buf, static_cast<size_t>(n));
  }
}

}  // namespace t2judge

namespace {

/// Collects failure messages (assertion text and the tests' hints).
class Collector : public ::testing::EmptyTestEventListener {
 public:
  std::string messages;
  void OnTestPartResult(const ::testing::TestPartResult& r) override {
    if (!r.failed() || messages.size() > 6000) return;
    messages += r.message();
    messages += "\n";
  }
};

int fd_option(const char* arg, const char* name) {
  const size_t n = std::strlen(name);
  return std::strncmp(arg, name, n) == 0 ? std::atoi(arg + n) : -1;
}

}  // namespace

int main(int argc, char** argv) {
  ::signal(SIGPIPE, SIG_IGN);  // a driver that died shows as an error on write, not a signal
  ::testing::InitGoogleTest(&argc, argv);
  auto& channel = t2judge::channel();
  bool list = false;
  for (int i = 1; i < argc; ++i) {
    if (std::strcmp(argv[i], "--t2-list") == 0) list = true;
    if (int fd = fd_option(argv[i], "--t2-calls="); fd >= 0) channel.calls = fd;
    if (int fd = fd_option(argv[i], "--t2-answers="); fd >= 0) channel.answers = fd;
  }
  auto& listeners = ::testing::UnitTest::GetInstance()->listeners();
  delete listeners.Release(listeners.default_result_printer());  // stdout carries the verdict only
  if (list) {
    const auto* u = ::testing::UnitTest::GetInstance();
    for (int i = 0; i < u->total_test_suite_count(); ++i) {
      const auto* s = u->GetTestSuite(i);
      for (int j = 0; j < s->total_test_count(); ++j)
        std::printf("%s.%s\n", s->name(), s->GetTestInfo(j)->name());
    }
    return 0;
  }
  auto* collector = new Collector;
  listeners.Append(collector);
  const int rc = RUN_ALL_TESTS();
  const auto* u = ::testing::UnitTest::GetInstance();
  const bool ok = rc == 0 && u->test_to_run_count() == 1 && u->successful_test_count() == 1;
  const char* verdict = channel.too_long ? "LIMIT" : channel.gone ? "GONE" : ok ? "PASS" : "FAIL";
  std::printf("%s\n%s", verdict, collector->messages.substr(0, 8000).c_str());
  return 0;
}
