// t2: the command line of the course. `t2 --help` lists the subcommands; each parses its own
// arguments with CLI11 (see command.hpp for how to add one; arguments.cpp is the tool's only
// file that includes CLI11).
#include <fmt/format.h>

#include <algorithm>
#include <cstdio>
#include <exception>
#include <memory>
#include <string>
#include <vector>

#include "command.hpp"
#include "t2/kernel/error.hpp"

namespace t2cli {

namespace {
std::vector<Command>& registry() {
  static std::vector<Command> r;
  return r;
}

void print_overview() {
  std::vector<Command> cs = commands();
  std::sort(cs.begin(), cs.end(), [](const Command& a, const Command& b) {
    return std::string(a.name) < b.name;
  });
  fmt::print(
      "t2 {} - computational geometry in the oriented projective plane T2\n\n"
      "Usage: t2 COMMAND [ARGS...]\n       t2 help COMMAND\n       t2 --version\n\nCommands:\n",
      T2_VERSION);
  for (const auto& c : cs) fmt::print("  {:<10} {}\n", c.name, c.summary);
  fmt::print(
      "\nExit status: 0 done, 1 a check failed, 2 bad usage or bad input,\n"
      "             3 the answer is undefined in T2 (the message says why).\n");
}

int usage_error(const Command& c, const std::string& message) {
  fmt::print(stderr, "t2 {}: {}\n(see t2 help {})\n", c.name, message, c.name);
  return kBadInput;
}
}  // namespace

void register_command(const Command& c) { registry().push_back(c); }
const std::vector<Command>& commands() { return registry(); }
const Command* find_command(const std::string& name) {
  for (const auto& c : registry())
    if (name == c.name) return &c;
  return nullptr;
}

}  // namespace t2cli

int main(int argc, char** argv) {
  using namespace t2cli;
  std::vector<std::string> args(argv + 1, argv + argc);
  if (args.empty() || args[0] == "--help" || args[0] == "-h") {
    print_overview();
    return args.empty() ? kBadInput : kOk;
  }
  if (args[0] == "--version") {
    fmt::print("t2 {}\n", T2_VERSION);
    return kOk;
  }
  if (args[0] == "help") {
    if (args.size() == 1) {
      print_overview();
      return kOk;
    }
    const Command* c = find_command(args[1]);
    if (!c) {
      fmt::print(stderr, "t2 help: no command named '{}' (see t2 --help)\n", args[1]);
      return kBadInput;
    }
    return print_help(*c);
  }
  const Command* c = find_command(args[0]);
  if (!c) {
    fmt::print(stderr, "t2: no command named '{}' (see t2 --help)\n", args[0]);
    return kBadInput;
  }
  try {
    return dispatch(*c, std::vector<std::string>(args.begin() + 1, args.end()));
  } catch (const UsageError& e) {
    return usage_error(*c, e.what());
  } catch (const t2::Undefined& e) {
    fmt::print(stderr, "t2 {}: undefined in T2: {}\n", c->name, e.what());
    return kUndefined;
  } catch (const std::exception& e) {
    // Bad input (parse errors carry file:line) and I/O failures.
    fmt::print(stderr, "{}\n", e.what());
    return kBadInput;
  }
}
