#pragma once
// The subcommands of the `t2` tool. Each lives in its own cmd_*.cpp and registers itself with
// T2_COMMAND, so adding a command never touches another file.

#include <span>
#include <stdexcept>
#include <string>
#include <vector>

namespace t2cli {

/// Exit statuses shared by every subcommand.
enum Exit : int {
  kOk = 0,         ///< done
  kFailed = 1,     ///< ran, and what it checked failed (e.g. `t2 book check` found drift)
  kBadInput = 2,   ///< bad usage or bad input
  kUndefined = 3,  ///< the answer is undefined in T² (the message says which rule)
};

using Args = std::span<const std::string>;

struct Command {
  const char* name;     ///< the word after `t2`
  const char* summary;  ///< one line for `t2 --help`
  const char* help;     ///< the full text of `t2 help NAME` (usage first)
  int (*run)(Args args);  ///< the arguments after the name; returns an Exit status
};

/// Thrown for bad usage; main prints "t2 NAME: message" and the usage line, exits 2.
class UsageError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

void register_command(const Command& c);
const std::vector<Command>& commands();
const Command* find_command(const std::string& name);

struct Registrar {
  explicit Registrar(const Command& c) { register_command(c); }
};

/// True when args hold -h or --help (each command answers it with its help text).
bool wants_help(Args args);

}  // namespace t2cli

#define T2_CONCAT_(a, b) a##b
#define T2_CONCAT(a, b) T2_CONCAT_(a, b)
/// Registers a subcommand: T2_COMMAND({"name", "summary", "help", run_function});
#define T2_COMMAND(...) \
  static const ::t2cli::Registrar T2_CONCAT(t2_command_, __LINE__){::t2cli::Command __VA_ARGS__};
