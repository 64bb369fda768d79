#pragma once
// The options of a subcommand, declared through a thin layer over CLI11 (arguments.cpp), so that
// CLI11's header is compiled in one file of the tool instead of in every command: CLI11 2.1
// defines its validators as objects at namespace scope, and a file that includes it spends about
// 4.5 s of GCC's time on them even through a precompiled header (measured on cmd_list.cpp).
//
// The names are CLI11's, so a command reads as a CLI11 program: app.add_option(...)->required()
// ->type_name("OUT")->check(IsMember({"a", "b"})). Only what the commands use is here; a new
// kind of option or check is one more declaration here and its definition in arguments.cpp.

#include <cstddef>
#include <cstdint>
#include <deque>
#include <functional>
#include <string>
#include <vector>

namespace CLI {
class App;
class Option;
}  // namespace CLI

namespace t2cli {

/// A check of an option's value, one of CLI11's: CLI::PositiveNumber, CLI::Range, CLI::IsMember.
/// (A check of one's own is a function: Option::check below.)
struct Check {
  enum class Kind { positive, range, member } kind;
  double low = 0, high = 0;
  std::vector<std::string> members;
};

/// The value is a number greater than 0.
inline const Check PositiveNumber{Check::Kind::positive, 0, 0, {}};
/// The value is a number in [low, high].
inline Check Range(double low, double high) { return Check{Check::Kind::range, low, high, {}}; }
/// The value is one of `members`.
inline Check IsMember(std::vector<std::string> members) {
  return Check{Check::Kind::member, 0, 0, std::move(members)};
}

/// One declared option; its setters return it, to be chained.
class Option {
 public:
  explicit Option(CLI::Option* o) : o_(o) {}
  Option* required();
  Option* type_name(const std::string& word);
  Option* check(const Check& c);
  /// A check of one's own: `what_is_wrong` returns what is wrong with a value, "" when nothing is.
  Option* check(std::function<std::string(const std::string&)> what_is_wrong);
  Option* delimiter(char c);

 private:
  CLI::Option* o_;
};

/// The command line of one subcommand, as its setup declares it.
class Arguments {
 public:
  explicit Arguments(CLI::App& app) : app_(app) {}
  Arguments(const Arguments&) = delete;
  Arguments& operator=(const Arguments&) = delete;

  /// An option (names "-o,--output") or a positional argument (a name without dashes) that fills
  /// `value`; T is std::string, a vector of them, std::optional<std::string>, std::filesystem::path,
  /// int, unsigned, std::size_t, std::uint64_t or double (arguments.cpp instantiates each).
  template <class T>
  Option* add_option(const std::string& names, T& value, const std::string& help = "");
  /// An option whose value is given to `f` as it is parsed.
  Option* add_option_function(const std::string& names, std::function<void(const std::string&)> f,
                              const std::string& help = "");
  /// A flag: `value` becomes true when it is given.
  Option* add_flag(const std::string& names, bool& value, const std::string& help = "");

  void description(const std::string& text);
  void footer(const std::string& text);
  /// Everything after the positional arguments goes to remaining() (t2 run).
  void prefix_command();
  std::vector<std::string> remaining() const;

 private:
  Option* keep(CLI::Option* o);
  CLI::App& app_;
  std::deque<Option> options_;
};

struct Command;

/// Prints the help of command c, generated from what its setup declares.
int print_help(const Command& c);

/// Parses `args` (what follows the command's name) as c declares them and runs c's action; bad
/// usage throws UsageError, -h or --help prints the help.
int dispatch(const Command& c, const std::vector<std::string>& args);

}  // namespace t2cli
