#pragma once
// The subcommands of the `t2` tool. Each lives in its own cmd_*.cpp and registers itself with
// T2_COMMAND, so adding a command never touches another file. Arguments are parsed by CLI11,
// through the layer of arguments.hpp (CLI11 itself is compiled in arguments.cpp only).
//
// How to add a command `t2 frob` (one new file, tools/t2/cmd_frob.cpp; the CMake glob finds it):
//
//   #include "command.hpp"
//   namespace t2cli {
//   namespace cmd_frob {                  // named after the file: a unity build
//                                         // compiles several commands in one translation unit
//   struct Options {                      // what the command line says, with the defaults
//     std::string file;
//     bool verbose = false;
//   };
//   int frob(const Options& o) { ...; return kOk; }   // the work; throws UsageError, t2::BadInput...
//   Action setup(Arguments& app) {
//     auto o = std::make_shared<Options>();
//     app.description("Frobs FILE. (Prose of the help, after the usage line.)");
//     app.add_option("FILE", o->file, "the scene file")->required();
//     app.add_flag("--verbose,-v", o->verbose, "say more");
//     app.footer("Exit status: 0 done; 2 bad usage or bad input.");
//     return [o] { return frob(*o); };
//   }
//   }  // namespace cmd_frob
//   T2_COMMAND({"frob", "one line for t2 --help", cmd_frob::setup});
//   }  // namespace t2cli
//
// One declaration per option: its names, the variable it fills, its help line, and its checks
// (->required(), ->check(Range(1, 256)), ->check(IsMember({"a", "b"})),
// ->type_name("OUT") for the word shown in the usage). arguments.cpp builds a CLI::App
// "t2 NAME" for the command, calls setup with it (as Arguments), parses the arguments after the
// name, and then runs the action.
// The help (`t2 NAME --help`, `t2 help NAME`) is generated: the usage line from the options in
// the order they were declared, the description, the options with their help lines, the footer.
// Bad usage (an unknown option, a missing value, a failed check, or UsageError thrown by the
// action) prints "t2 NAME: what is wrong" and "(see t2 help NAME)" and exits 2. A command that
// passes its trailing arguments to another program (t2 run) calls app.prefix_command() and reads
// app.remaining().

#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

#include "arguments.hpp"


namespace t2cli {

/// Exit statuses shared by every subcommand.
enum Exit : int {
  kOk = 0,         ///< done
  kFailed = 1,     ///< ran, and what it checked failed (e.g. `t2 book check` found drift)
  kBadInput = 2,   ///< bad usage or bad input
  kUndefined = 3,  ///< the answer is undefined in T² (the message says which rule)
};

/// The work of a command once its arguments are parsed; returns an Exit status.
using Action = std::function<int()>;

/// Declares a command's options on `app` (bound to state the returned Action owns).
using Setup = Action (*)(Arguments& app);

struct Command {
  const char* name;     ///< the word after `t2`
  const char* summary;  ///< one line for `t2 --help`
  Setup setup;          ///< declares the options, returns the action
};

/// Thrown for bad usage; main prints "t2 NAME: message" and "(see t2 help NAME)", exits 2.
class UsageError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// The names of a library enum's published list (t2::hull_algorithms, t2::layers_methods...),
/// each by its `name` overload: a command's choices come from the library, never a copy.
template <class Values>
std::vector<std::string> names_of(const Values& values) {
  std::vector<std::string> names;
  for (auto v : values) names.emplace_back(name(v));
  return names;
}

void register_command(const Command& c);
const std::vector<Command>& commands();
const Command* find_command(const std::string& name);

struct Registrar {
  explicit Registrar(const Command& c) { register_command(c); }
};

}  // namespace t2cli

#define T2_CONCAT_(a, b) a##b
#define T2_CONCAT(a, b) T2_CONCAT_(a, b)
/// Registers a subcommand: T2_COMMAND({"name", "summary", setup_function});
#define T2_COMMAND(...) \
  static const ::t2cli::Registrar T2_CONCAT(t2_command_, __COUNTER__){::t2cli::Command __VA_ARGS__};
