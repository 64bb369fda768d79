// The main() of the driver: the only program that runs student code. It reads calls (one per
// line, judge_wire.hpp) from the fd given by --t2-calls, calls the student's function through
// the exercise's table (remote.cpp) and writes each answer line to the fd given by --t2-answers.
// stdout and stderr are the student's own (capped or discarded by the grader: printing costs
// nothing). The driver decides nothing: a wrong, missing or forged answer is only an answer,
// which the checker (another process, never linked with student code) compares.
#include <unistd.h>

#include <cstdlib>
#include <cstring>
#include <exception>
#include <sstream>
#include <string>

#include "judge_wire.hpp"

namespace {

std::string one_line(std::string s) {
  for (auto& c : s)
    if (c == '\n' || c == '\r') c = ' ';
  return s.substr(0, 500);
}

// Answers one call line.
std::string answer(const std::string& line) {
  std::istringstream in(line);
  std::string name;
  in >> name;
  const auto& t = t2judge::table();
  const auto it = t.find(name);
  if (it == t.end()) return "E other unknown call " + one_line(name);
  try {
    return it->second(in);
  } catch (const t2::Undefined& e) {
    return "E undefined " + one_line(e.what());
  } catch (const t2::BadInput& e) {
    return "E bad_input " + one_line(e.what());
  } catch (const std::exception& e) {
    return "E other " + one_line(e.what());
  } catch (...) {
    return "E other an exception that is not a std::exception";
  }
}

}  // namespace

int main(int argc, char** argv) {
  int calls = -1, answers = -1;
  for (int i = 1; i < argc; ++i) {
    if (std::strncmp(argv[i], "--t2-calls=", 11) == 0) calls = std::atoi(argv[i] + 11);
    if (std::strncmp(argv[i], "--t2-answers=", 13) == 0) answers = std::atoi(argv[i] + 13);
  }
  if (calls < 0 || answers < 0) return 2;
  std::string pending;
  char buf[65536];
  for (;;) {
    const auto nl = pending.find('\n');
    if (nl == std::string::npos) {
      const ssize_t n = ::read(calls, buf, sizeof buf);
      if (n <= 0) return 0;  // the checker is done
      pending.append(buf, static_cast<size_t>(n));
      continue;
    }
    const std::string line = pending.substr(0, nl);
    pending.erase(0, nl + 1);
    if (!t2judge::write_all(answers, answer(line) + "\n")) return 0;
  }
}
