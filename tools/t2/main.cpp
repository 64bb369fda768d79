// t2: the command line of the course. `t2 --help` lists the subcommands; each parses its own
// arguments with CLI11 (see command.hpp for how to add one).
#include <CLI/CLI.hpp>
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

/// The help of a command, in the shape of the hand-written texts it replaced:
///   Usage: t2 NAME ARG [--flag] [--option VALUE] ...   (generated, in declaration order)
///   <description>
///   Arguments: / Options: one line each, with their help lines
///   <footer>
class Help : public CLI::Formatter {
 public:
  std::string make_usage(const CLI::App* app, std::string name) const override {
    std::string out = "Usage: " + name;
    for (const CLI::Option* o : app->get_options()) {
      if (o == app->get_help_ptr()) continue;
      std::string word = o->get_positional() ? o->get_name(true, false) : shortest_long_name(o);
      if (!o->get_positional() && !type_word(o).empty()) word += " " + type_word(o);
      if (o->get_expected_max() > 1) word += "...";
      out += " " + (o->get_required() ? word : "[" + word + "]");
    }
    if (app->get_prefix_command()) out += " [ARGS...]";
    return out + "\n";
  }

  std::string make_help(const CLI::App* app, std::string name, CLI::AppFormatMode) const override {
    std::string out = make_usage(app, name);
    if (!app->get_description().empty()) out += "\n" + app->get_description() + "\n";
    std::vector<const CLI::Option*> args, opts;
    for (const CLI::Option* o : app->get_options()) {
      if (o == app->get_help_ptr() || o->get_description().empty()) continue;
      (o->get_positional() ? args : opts).push_back(o);
    }
    out += group(args, true) + group(opts, false);
    if (!app->get_footer().empty()) out += "\n" + app->get_footer() + "\n";
    return out;
  }

 private:
  // The word for an option's value (OUT, DIR, N), without what CLI11 appends for its checks.
  static std::string type_word(const CLI::Option* o) {
    const std::string t = o->get_type_name();
    return t.substr(0, t.find(':'));
  }

  // The name shown in the usage line: the long one (--jobs) when there is one.
  static std::string shortest_long_name(const CLI::Option* o) {
    if (!o->get_lnames().empty()) return "--" + o->get_lnames().front();
    return "-" + o->get_snames().front();
  }

  static std::string group(const std::vector<const CLI::Option*>& os, bool positional) {
    if (os.empty()) return "";
    std::vector<std::string> names;
    std::size_t width = 0;
    for (const CLI::Option* o : os) {
      std::string n;
      if (positional) {
        n = o->get_name(true, false);
      } else {
        for (const auto& s : o->get_snames()) n += (n.empty() ? "-" : ", -") + s;
        for (const auto& l : o->get_lnames()) n += (n.empty() ? "--" : ", --") + l;
        if (!type_word(o).empty()) n += " " + type_word(o);
      }
      if (n.size() <= 20) width = std::max(width, n.size());  // longer ones get a line of their own
      names.push_back(n);
    }
    std::string out = positional ? "\nArguments:\n" : "\nOptions:\n";
    for (std::size_t i = 0; i < os.size(); ++i) {
      std::string line = fmt::format("  {:<{}}  ", names[i], width);
      if (names[i].size() > width) line = "  " + names[i] + "\n" + std::string(width + 4, ' ');
      for (char c : os[i]->get_description()) {
        line += c;
        if (c == '\n') line += std::string(width + 4, ' ');
      }
      out += line + "\n";
    }
    return out;
  }
};

/// The CLI11 application of command c, its options declared; `action` receives what to run.
std::unique_ptr<CLI::App> make_app(const Command& c, Action& action) {
  auto app = std::make_unique<CLI::App>(std::string(), std::string("t2 ") + c.name);
  app->formatter(std::make_shared<Help>());
  app->set_help_flag("-h,--help", "print this help");
  action = c.setup(*app);
  return app;
}

int print_help(const Command& c) {
  Action action;
  const auto app = make_app(c, action);
  fmt::print("{}", app->help());
  return kOk;
}

int usage_error(const Command& c, const std::string& message) {
  fmt::print(stderr, "t2 {}: {}\n(see t2 help {})\n", c.name, message, c.name);
  return kBadInput;
}

// Parses the arguments of c, then runs it.
int dispatch(const Command& c, const std::vector<std::string>& rest) {
  Action action;
  const auto app = make_app(c, action);
  try {
    app->parse(std::vector<std::string>(rest.rbegin(), rest.rend()));  // CLI11 takes them reversed
  } catch (const CLI::Success&) {  // -h or --help
    fmt::print("{}", app->help());
    return kOk;
  } catch (const CLI::ParseError& e) {
    return usage_error(c, e.what());
  }
  return action();
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
