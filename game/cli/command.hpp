// Subcommand registry. Each subcommand lives in its own file in game/cli/ and registers
// itself with a static CommandRegistrar, so adding a command never edits main.cpp.
//
// setup() adds the subcommand's options to `sub` and returns the function that runs it
// after parsing, with the one Assets context of the process. run() returns the exit code:
// 0 ok, 1 a check failed (regress drift, unreachable fit), 2 bad input, 3 no off-screen
// OpenGL. Throwing sweetspot::InputError exits 2 with its message; any other exception is
// an internal error, exit 4.
#pragma once

#include <charconv>
#include <cmath>
#include <cstdint>

#include <functional>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "game/content/assets.hpp"
#include "physics/error.hpp"
#include "physics/range.hpp"

namespace sweetspot::cli {

using RunFn = std::function<int(const Assets&)>;

/// A seed flag's text: a whole number in [0, 2^64 - 1], nothing else. CLI11 alone would wrap
/// "-1" and clamp "99999999999999999999" to the largest value, silently.
inline const CLI::Validator kSeedText(
    [](std::string& text) -> std::string {
      std::uint64_t v = 0;
      const char* end = text.data() + text.size();
      const auto [p, ec] = std::from_chars(text.data(), end, v);
      if (text.empty() || ec != std::errc() || p != end)
        return "'" + text + "' is not a whole number in [0, 18446744073709551615]";
      return {};
    },
    "UINT64");
/// Every option that takes a value refuses "" (main.cpp adds it to all of them).
inline const CLI::Validator kNotEmpty(
    [](std::string& text) -> std::string {
      return text.empty() ? "an empty value: give one, or leave the option out for its default" : std::string();
    },
    "");
/// A number flag within [lo, hi]. CLI::Range alone lets "nan" through (no comparison with
/// NaN is true), which a run would then read as the flag left out.
inline CLI::Validator finite_range(double lo, double hi) {
  const Range range{lo, hi};
  const std::string allowed = range_text(range, "");
  return CLI::Validator(
      [range, allowed](std::string& text) -> std::string {
        double v = 0.0;
        const char* end = text.data() + text.size();
        const auto [p, ec] = std::from_chars(text.data(), end, v);
        if (text.empty() || ec != std::errc() || p != end || std::isnan(v)) return "'" + text + "' is not a number (allowed " + allowed + ")";
        if (!range.contains(v)) return text + " is out of range (allowed " + allowed + ")";
        return {};
      },
      "NUMBER in " + allowed);
}
/// A whole-number flag within [lo, hi], refused in the words finite_range uses ("55 is out of
/// range (allowed [0, 54])"); "2.5" or "abc" is not a whole number.
template <class T>
CLI::Validator int_range(T lo, T hi) {
  const std::string allowed = "[" + std::to_string(lo) + ", " + std::to_string(hi) + "]";
  return CLI::Validator(
      [lo, hi, allowed](std::string& text) -> std::string {
        T v{};
        const char* end = text.data() + text.size();
        const auto [p, ec] = std::from_chars(text.data(), end, v);
        if (ec == std::errc::result_out_of_range || (ec == std::errc() && p == end && (v < lo || v > hi)))
          return text + " is out of range (allowed " + allowed + ")";
        if (text.empty() || ec != std::errc() || p != end) return "'" + text + "' is not a whole number (allowed " + allowed + ")";
        return {};
      },
      "INT in " + allowed);
}
/// A flag checked by the model's own lookup (a skill, a format): its InputError's message
/// becomes the flag's error, so the one list of allowed values stays with the model.
template <class Check>
CLI::Validator checked_by(Check check, std::string description) {
  return CLI::Validator(
      [check](std::string& text) -> std::string {
        try {
          check(text);
          return {};
        } catch (const InputError& e) {
          return e.what();
        }
      },
      std::move(description));
}
using SetupFn = RunFn (*)(CLI::App& sub);

struct CommandInfo {
  int order;            ///< position in `sweetspot --help`
  const char* name;
  const char* summary;
  SetupFn setup;
};

std::vector<CommandInfo>& command_registry();

struct CommandRegistrar {
  CommandRegistrar(int order, const char* name, const char* summary, SetupFn setup) {
    command_registry().push_back({order, name, summary, setup});
  }
};

}  // namespace sweetspot::cli
