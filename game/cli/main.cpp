// `sweetspot`: dispatches to the subcommands registered in game/cli/cmd_*.cpp.
#include <algorithm>
#include <string>
#include <csignal>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <iostream>

#include "game/cli/command.hpp"
#include "game/util/terminal_text.hpp"
#include "physics/error.hpp"

namespace sweetspot::cli {
std::vector<CommandInfo>& command_registry() {
  static std::vector<CommandInfo> registry;
  return registry;
}
}  // namespace sweetspot::cli

namespace {

/// An error message quotes what the user wrote, often twice (the flag and the key's value),
/// and must stay one readable line: control characters are shown escaped ("\n"), and a
/// run of over 240 characters without a space (a 100 kB argument) keeps its first 160 and
/// last 40, with the count of what was left out between.
std::string printable_message(const std::string& message) {
  const std::string text = sweetspot::terminal_safe(message);
  constexpr std::size_t kLong = 240, kHead = 160, kTail = 40;
  std::string out;
  for (std::size_t i = 0; i < text.size();) {
    const std::size_t end = std::min(text.find(' ', i), text.size());
    if (end - i > kLong) {
      out.append(text, i, kHead);
      out += "...(" + std::to_string(end - i - kHead - kTail) + " more characters)...";
      out.append(text, end - kTail, kTail);
    } else {
      out.append(text, i, end - i);
    }
    if (end < text.size()) out += ' ';
    i = end + 1;
  }
  return out;
}

/// True when what was printed on stdout never arrived (a full disk, /dev/full, a closed
/// stdout); the message is printed here.
bool stdout_failed() {
  std::cout.flush();
  if (std::cout && std::fflush(stdout) == 0 && std::ferror(stdout) == 0) return false;
  std::cerr << "sweetspot: error: writing the output to stdout failed (disk full, or stdout closed)\n";
  return true;
}

/// CLI11 says only "Could not convert: --balls = x" when a flag's value is not a number;
/// this says what the flag takes, from its help text (which gives the range).
std::string conversion_help(const CLI::App* top, const CLI::Error& e) {
  const std::string what = e.what();
  // CLI11 says "--seed: At Most 1 required but received 2" for an option given twice.
  if (e.get_name() == "ArgumentMismatch") {
    constexpr std::string_view kTwice = ": At Most 1 required but received ";
    const auto colon = what.find(kTwice);
    if (colon != std::string::npos)
      return what.substr(0, colon) + ": given " + what.substr(colon + kTwice.size()) + " times; it takes one value, so give it once";
  }
  if (e.get_name() != "ConversionError") return what;
  const auto colon = what.find(": "), eq = what.find(" = ");
  if (colon == std::string::npos || eq == std::string::npos || eq < colon) return what;
  const std::string flag = what.substr(colon + 2, eq - colon - 2), value = what.substr(eq + 3);
  for (const CLI::App* sub : top->get_subcommands([](const CLI::App* a) { return a->parsed(); })) {
    const CLI::Option* opt = sub->get_option_no_throw(flag);
    if (opt == nullptr) continue;
    return flag + ": '" + value + "' is not a value it takes: " + opt->get_description();
  }
  return what;
}

}  // namespace

int main(int argc, char** argv) {
  using namespace sweetspot::cli;
  // Over a file-size limit (ulimit -f) a write must fail with EFBIG and be reported, not
  // kill the process with SIGXFSZ halfway through a file.
  std::signal(SIGXFSZ, SIG_IGN);
  CLI::App app{"Sweetspot — golf and baseball impact simulation"};
  app.require_subcommand(1);
  app.set_version_flag("--version", "sweetspot 0.1");
  // Usage errors read like every other error: prefixed, one per line, pointing at --help.
  app.failure_message([](const CLI::App* top, const CLI::Error& e) {
    return std::string("sweetspot: error: ") + conversion_help(top, e) + " (run with --help for the options and their ranges)\n";
  });

  auto& registry = command_registry();
  // The name breaks a tie: the order of static initialisation across files is unspecified.
  std::sort(registry.begin(), registry.end(), [](const CommandInfo& a, const CommandInfo& b) {
    return a.order != b.order ? a.order < b.order : std::string_view(a.name) < std::string_view(b.name);
  });
  std::vector<std::pair<CLI::App*, RunFn>> runs;
  for (const auto& c : registry) {
    CLI::App* sub = app.add_subcommand(c.name, c.summary);
    runs.emplace_back(sub, c.setup(*sub));
    // One rule for empty values: `--world ""` is a mistake (an unset variable in a script),
    // never a way to ask for the default, so every option that takes a value refuses "".
    // (Nested subcommands too: `course import --name ""`.)
    const std::function<void(CLI::App*)> refuse_empty = [&](CLI::App* a) {
      for (CLI::Option* opt : a->get_options())
        if (opt->get_type_size() > 0) opt->check(kNotEmpty);
      for (CLI::App* nested : a->get_subcommands({})) refuse_empty(nested);
    };
    refuse_empty(sub);
  }

  // A mistyped command (`sweetspot fly`) is named, with the commands there are; CLI11 alone
  // would only say that a subcommand is required.
  const auto is_command = [&](const char* word) {
    return std::any_of(registry.begin(), registry.end(), [&](const CommandInfo& c) { return std::string(c.name) == word; });
  };
  if (argc > 1 && argv[1][0] != '-' && !is_command(argv[1])) {
    std::string names;
    for (const auto& c : registry) names += std::string(names.empty() ? "" : ", ") + c.name;
    std::cerr << "sweetspot: error: " << printable_message("unknown command '" + std::string(argv[1]) + "' (commands: " + names + ")")
              << "\n";
    return 2;
  }
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    // CLI11 prints usage errors; map every bad flag to exit 2 (help/version stay 0).
    const int code = app.exit(e);
    if (code == 0 && stdout_failed()) return 2;  // help and version are output too
    return code == 0 ? 0 : 2;
  }

  try {
    const sweetspot::Assets assets;  // the one asset context; each part loads on first use
    for (auto& [sub, run] : runs) {
      if (!sub->parsed()) continue;
      const int code = run(assets);
      return stdout_failed() ? 2 : code;  // output that never arrived is a failure
    }
  } catch (const sweetspot::InputError& e) {
    std::cerr << "sweetspot: error: " << printable_message(e.what()) << "\n";
    return 2;
  } catch (const std::filesystem::filesystem_error& e) {
    // A path the OS refuses is the user's input, not our bug; loaders report most as
    // InputError already, this catches any that slip through.
    std::cerr << "sweetspot: error: " << printable_message(e.what()) << "\n";
    return 2;
  } catch (const std::exception& e) {
    std::cerr << "sweetspot: internal error: " << printable_message(e.what()) << "\n";
    return 4;
  }
  return 2;
}
