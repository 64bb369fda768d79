// The layer over CLI11 of arguments.hpp (every call goes to CLI11 as it is), and the parsing and
// the help of a command: the tool's one file that includes CLI11.
#include "arguments.hpp"

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include <algorithm>
#include <filesystem>
#include <memory>
#include <optional>

#include "command.hpp"

namespace t2cli {

Option* Option::required() {
  o_->required();
  return this;
}

Option* Option::type_name(const std::string& word) {
  o_->type_name(word);
  return this;
}

Option* Option::check(const Check& c) {
  switch (c.kind) {
    case Check::Kind::positive: o_->check(CLI::PositiveNumber); break;
    case Check::Kind::range: o_->check(CLI::Range(c.low, c.high)); break;
    case Check::Kind::member: o_->check(CLI::IsMember(c.members)); break;
  }
  return this;
}

Option* Option::check(std::function<std::string(const std::string&)> what_is_wrong) {
  o_->check(std::move(what_is_wrong));
  return this;
}

Option* Option::delimiter(char c) {
  o_->delimiter(c);
  return this;
}

Option* Arguments::keep(CLI::Option* o) { return &options_.emplace_back(o); }

template <class T>
Option* Arguments::add_option(const std::string& names, T& value, const std::string& help) {
  return keep(app_.add_option(names, value, help));
}

template Option* Arguments::add_option(const std::string&, std::string&, const std::string&);
template Option* Arguments::add_option(const std::string&, std::vector<std::string>&, const std::string&);
template Option* Arguments::add_option(const std::string&, int&, const std::string&);
template Option* Arguments::add_option(const std::string&, unsigned&, const std::string&);
template Option* Arguments::add_option(const std::string&, unsigned long&, const std::string&);
template Option* Arguments::add_option(const std::string&, unsigned long long&, const std::string&);
template Option* Arguments::add_option(const std::string&, double&, const std::string&);
template Option* Arguments::add_option(const std::string&, std::optional<std::string>&, const std::string&);
template Option* Arguments::add_option(const std::string&, std::filesystem::path&, const std::string&);

Option* Arguments::add_option_function(const std::string& names, std::function<void(const std::string&)> f,
                                       const std::string& help) {
  return keep(app_.add_option_function<std::string>(names, std::move(f), help));
}

Option* Arguments::add_flag(const std::string& names, bool& value, const std::string& help) {
  return keep(app_.add_flag(names, value, help));
}

void Arguments::description(const std::string& text) { app_.description(text); }
void Arguments::footer(const std::string& text) { app_.footer(text); }
void Arguments::prefix_command() { app_.prefix_command(); }
std::vector<std::string> Arguments::remaining() const { return app_.remaining(); }

namespace {

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

/// The CLI11 application of command c with its options declared (through `arguments`, which
/// lives as long as it), and the action to run once they are parsed.
struct Parser {
  explicit Parser(const Command& c) : app(std::string(), std::string("t2 ") + c.name), arguments(app) {
    app.formatter(std::make_shared<Help>());
    app.set_help_flag("-h,--help", "print this help");
    action = c.setup(arguments);
  }
  CLI::App app;
  Arguments arguments;
  Action action;
};

}  // namespace

int print_help(const Command& c) {
  Parser p(c);
  fmt::print("{}", p.app.help());
  return kOk;
}

int dispatch(const Command& c, const std::vector<std::string>& rest) {
  Parser p(c);
  try {
    p.app.parse(std::vector<std::string>(rest.rbegin(), rest.rend()));  // CLI11 takes them reversed
  } catch (const CLI::Success&) {  // -h or --help
    fmt::print("{}", p.app.help());
    return kOk;
  } catch (const CLI::ParseError& e) {
    throw UsageError(e.what());
  }
  return p.action();
}

}  // namespace t2cli
