// Runs a piece of work in a forked child process and brings its result back as bytes.
//
// Why: assimp (Debian 12's 5.2.5) has memory-safety bugs in its OBJ/MTL parsers that a
// hostile file can reach (our fuzzer found a wild write in the material-library parser).
// We cannot fix the library, so the import runs where a crash, a hang or a runaway
// allocation costs only a child process: the caller gets a clear IsolationFailure and the
// game, the CLI and their half-written outputs are untouched.
#pragma once

#include <functional>
#include <stdexcept>
#include <string>

namespace sweetspot {

/// Why the isolated work produced no result: it crashed (a signal), ran past its time, ran
/// out of memory, or threw. `what()` is a sentence fit for the user's message.
class IsolationFailure : public std::runtime_error {
 public:
  IsolationFailure(const std::string& what, bool thrown_by_work) : std::runtime_error(what), thrown_by_work_(thrown_by_work) {}
  /// True when the work itself threw (what() is its message), false when the child died
  /// or passed a limit (what() says how).
  bool thrown_by_work() const { return thrown_by_work_; }

 private:
  bool thrown_by_work_;
};

struct IsolationLimits {
  /// Wall-clock limit for the child, s: generous for any mesh under the 256 MiB file limit
  /// (our largest shipped world imports in well under a second), and the end of a hang.
  double wall_seconds = 120.0;
  /// Address space the child may add to the parent's, bytes (ignored in sanitizer builds,
  /// whose shadow memory reserves terabytes). 4 GiB: ~16x the largest mesh file we accept.
  unsigned long long extra_address_space = 4ULL << 30;
};

/// Runs `work` in a child process and returns the bytes it returned. A std::exception the
/// work throws comes back as IsolationFailure with its what() text, so the caller can turn
/// it into its own error type. Throws IsolationFailure when the child dies by a signal,
/// exits without a complete answer, or passes a limit.
std::string run_isolated(const std::function<std::string()>& work, const IsolationLimits& limits = {});

}  // namespace sweetspot
