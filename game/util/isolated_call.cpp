#include "game/util/isolated_call.hpp"

#include <fcntl.h>
#include <poll.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <exception>
#include <new>

#if defined(__SANITIZE_ADDRESS__)
#define SWEETSPOT_ASAN 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define SWEETSPOT_ASAN 1
#endif
#endif

// Set by sanitizer runtimes (and by libFuzzer, to save a crashing input). Weak: null in a
// plain build. The child clears it so a library bug it contains is not reported as ours.
extern "C" void __sanitizer_set_death_callback(void (*callback)(void)) __attribute__((weak));

namespace sweetspot {
namespace {

constexpr char kResult = 'R';
constexpr char kError = 'E';    // the work threw: its message follows
constexpr char kFailure = 'F';  // the child failed around the work: why follows
/// The largest answer the parent accepts, bytes: a 256 MiB OBJ's triangles as floats are
/// well under this, so a child writing more is broken.
constexpr std::size_t kMaxAnswerBytes = std::size_t{2} << 30;

bool write_all(int fd, const char* data, std::size_t size) {
  while (size > 0) {
    const ssize_t n = ::write(fd, data, size);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return false;
    data += n;
    size -= static_cast<std::size_t>(n);
  }
  return true;
}

/// The child's whole life: limits, the work, the answer, _exit (no atexit handlers, no
/// leak checker, no flushing of stdio buffers the parent also holds).
[[noreturn]] void child_main(int out, const std::function<std::string()>& work, const IsolationLimits& limits) {
  if (__sanitizer_set_death_callback != nullptr) __sanitizer_set_death_callback(nullptr);
  // Crashes end the child by their signal (the parent names it); Ctrl-C ends it plainly
  // rather than running the parent's temp-file cleanup a second time.
  for (const int sig : {SIGSEGV, SIGBUS, SIGFPE, SIGILL, SIGABRT, SIGINT, SIGTERM, SIGPIPE}) std::signal(sig, SIG_DFL);
  if (const int devnull = ::open("/dev/null", O_WRONLY | O_CLOEXEC); devnull >= 0) ::dup2(devnull, STDERR_FILENO);
  const auto cpu = static_cast<rlim_t>(limits.wall_seconds) + 1;
  const rlimit cpu_limit{cpu, cpu + 1};
  ::setrlimit(RLIMIT_CPU, &cpu_limit);
#if !defined(SWEETSPOT_ASAN)
  if (std::FILE* statm = std::fopen("/proc/self/statm", "r")) {
    unsigned long long pages = 0;
    if (std::fscanf(statm, "%llu", &pages) == 1) {
      const auto bytes = pages * static_cast<unsigned long long>(::sysconf(_SC_PAGESIZE)) + limits.extra_address_space;
      const rlimit as_limit{static_cast<rlim_t>(bytes), static_cast<rlim_t>(bytes)};
      ::setrlimit(RLIMIT_AS, &as_limit);
    }
    std::fclose(statm);
  }
#endif
  std::string answer;
  try {
    answer = work();
    answer.insert(answer.begin(), kResult);
  } catch (const std::bad_alloc&) {
    answer = std::string(1, kFailure) + "ran out of memory (over " +
             std::to_string(limits.extra_address_space >> 30) + " GiB)";
  } catch (const std::exception& e) {
    answer = std::string(1, kError) + e.what();
  } catch (...) {
    answer = std::string(1, kFailure) + "failed with an unknown error";
  }
  const bool sent = write_all(out, answer.data(), answer.size());
  ::_exit(sent ? 0 : 3);
}

std::string describe(int status) {
  if (WIFSIGNALED(status)) {
    const int sig = WTERMSIG(status);
    if (sig == SIGXCPU || sig == SIGKILL) return "ran out of time or memory";
    return std::string("crashed (signal ") + std::to_string(sig) + ", " + ::strsignal(sig) + ")";
  }
  if (WIFEXITED(status)) return "stopped with exit code " + std::to_string(WEXITSTATUS(status));
  return "ended abnormally";
}

}  // namespace

std::string run_isolated(const std::function<std::string()>& work, const IsolationLimits& limits) {
  int fds[2];
  if (::pipe2(fds, O_CLOEXEC) != 0) throw IsolationFailure(std::string("cannot create a pipe: ") + std::strerror(errno), false);
  std::fflush(nullptr);  // so the child's copy of a stdio buffer can never be written twice
  const pid_t pid = ::fork();
  if (pid < 0) {
    const int err = errno;
    ::close(fds[0]);
    ::close(fds[1]);
    throw IsolationFailure(std::string("cannot start a process: ") + std::strerror(err), false);
  }
  if (pid == 0) {
    ::close(fds[0]);
    child_main(fds[1], work, limits);
  }
  ::close(fds[1]);

  std::string answer;
  bool timed_out = false;
  bool too_big = false;
  const auto deadline =
      std::chrono::steady_clock::now() + std::chrono::duration<double>(limits.wall_seconds);
  char chunk[1 << 16];
  for (;;) {
    const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - std::chrono::steady_clock::now());
    if (left.count() <= 0) {
      timed_out = true;
      break;
    }
    pollfd p{fds[0], POLLIN, 0};
    const int ready = ::poll(&p, 1, static_cast<int>(std::min<long long>(left.count(), 1000)));
    if (ready < 0 && errno == EINTR) continue;
    if (ready < 0) break;
    if (ready == 0) continue;
    const ssize_t n = ::read(fds[0], chunk, sizeof chunk);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) break;  // end of the answer (or a broken pipe: judged by the exit status)
    answer.append(chunk, static_cast<std::size_t>(n));
    if (answer.size() > kMaxAnswerBytes) {
      too_big = true;
      break;
    }
  }
  ::close(fds[0]);
  if (timed_out || too_big) ::kill(pid, SIGKILL);
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0) {
    if (errno != EINTR) throw IsolationFailure(std::string("lost its worker process: ") + std::strerror(errno), false);
  }
  if (timed_out)
    throw IsolationFailure("ran past its time limit of " + std::to_string(static_cast<long>(limits.wall_seconds)) + " s", false);
  if (too_big) throw IsolationFailure("produced an answer over 2 GiB", false);
  if (!(WIFEXITED(status) && WEXITSTATUS(status) == 0) || answer.empty()) throw IsolationFailure(describe(status), false);
  if (answer.front() == kError) throw IsolationFailure(answer.substr(1), true);
  if (answer.front() == kFailure) throw IsolationFailure(answer.substr(1), false);
  answer.erase(answer.begin());
  return answer;
}

}  // namespace sweetspot
