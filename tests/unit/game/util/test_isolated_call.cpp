// Isolated work: the answer comes back byte for byte; a crash, a hang, a throw or a child
// that exits early each come back as a failure that says which, and the caller lives on.
#include <catch2/catch.hpp>

#include <unistd.h>

#include <csignal>
#include <cstdlib>
#include <stdexcept>
#include <string>

#include "game/util/isolated_call.hpp"

using namespace sweetspot;
using Catch::Matchers::Contains;

namespace {
/// The failure run_isolated threw for `work`, or a test failure when it returned.
IsolationFailure failure_of(const std::function<std::string()>& work, IsolationLimits limits = {}) {
  try {
    run_isolated(work, limits);
  } catch (const IsolationFailure& e) {
    return e;
  }
  FAIL("run_isolated returned where it should have failed");
  return IsolationFailure("", false);
}
}  // namespace

TEST_CASE("isolated work returns its bytes unchanged, NUL and high bytes included", "[isolation][hostile]") {
  std::string bytes;
  for (int k = 0; k < 300000; ++k) bytes.push_back(static_cast<char>(k * 37 % 256));  // > one pipe buffer
  CHECK(run_isolated([&] { return bytes; }) == bytes);
  CHECK(run_isolated([] { return std::string(); }).empty());
}

TEST_CASE("a crash in isolated work is a failure naming the signal, not a crash of the caller",
          "[isolation][hostile]") {
  const IsolationFailure segv = failure_of([]() -> std::string {
    std::raise(SIGSEGV);
    return "unreachable";
  });
  CHECK_FALSE(segv.thrown_by_work());
  CHECK_THAT(segv.what(), Contains("crashed") && Contains("signal 11"));
  const IsolationFailure abrt = failure_of([]() -> std::string { std::abort(); });
  CHECK_THAT(abrt.what(), Contains("crashed") && Contains("signal 6"));
}

TEST_CASE("isolated work that hangs is stopped at its time limit", "[isolation][hostile]") {
  IsolationLimits limits;
  limits.wall_seconds = 0.5;
  const IsolationFailure hang = failure_of(
      []() -> std::string {
        for (;;) ::pause();
      },
      limits);
  CHECK_FALSE(hang.thrown_by_work());
  CHECK_THAT(hang.what(), Contains("time limit"));
}

TEST_CASE("isolated work that throws or exits comes back as a failure that says so", "[isolation][hostile]") {
  const IsolationFailure thrown = failure_of([]() -> std::string { throw std::runtime_error("bad vertex 7"); });
  CHECK(thrown.thrown_by_work());
  CHECK(std::string(thrown.what()) == "bad vertex 7");
  const IsolationFailure exited = failure_of([]() -> std::string { ::_exit(5); });
  CHECK_FALSE(exited.thrown_by_work());
  CHECK_THAT(exited.what(), Contains("exit code 5"));
}
