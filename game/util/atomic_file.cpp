// write_file_atomic: mkstemp next to the target (rename is atomic only within one file
// system), write everything, fsync the file, rename, then fsync the directory so the new
// name survives a power loss too.
#include "game/util/atomic_file.hpp"

#include <fcntl.h>
#include <limits.h>
#include <sys/stat.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <csignal>
#include <cstring>
#include <functional>
#include <mutex>
#include <set>
#include <tuple>
#include <string>
#include <stdexcept>
#include <vector>

#include "physics/error.hpp"

namespace sweetspot {
namespace {

namespace fs = std::filesystem;

[[noreturn]] void fail(const fs::path& path, const std::string& what, int err) {
  throw InputError("cannot write '" + path.string() + "': " + what + (err != 0 ? std::string(": ") + std::strerror(err) : ""));
}

// The temporary files on disk, for the signal handler to remove: the one being written and
// those an OutputBatch holds until its commit. Fixed buffers and lock-free flags because a
// handler may only call async-signal-safe functions (unlink). The writers in this program
// run one at a time (the UI thread or the CLI), so a few slots are enough.
constexpr int kTempSlots = 8;
char g_temp_path[kTempSlots][PATH_MAX];
std::atomic<bool> g_temp_live[kTempSlots];
static_assert(std::atomic<bool>::is_always_lock_free);

extern "C" void remove_temp_and_reraise(int sig) {
  for (int i = 0; i < kTempSlots; ++i)
    if (g_temp_live[i].load()) ::unlink(g_temp_path[i]);
  std::signal(sig, SIG_DFL);
  std::raise(sig);
}

// Installs the cleanup handler for SIGINT/SIGTERM unless someone else (the connect server's
// Asio signal_set, a test runner) already handles them.
void install_cleanup_handlers() {
  static std::once_flag once;
  std::call_once(once, [] {
    for (const int sig : {SIGINT, SIGTERM}) {
      struct sigaction old {};
      if (::sigaction(sig, nullptr, &old) == 0 && old.sa_handler == SIG_DFL) std::signal(sig, remove_temp_and_reraise);
    }
    // Over a file-size limit (ulimit -f) write() must fail with EFBIG, reported like a full
    // disk; by default SIGXFSZ would kill the process and leave the temporary behind.
    struct sigaction old {};
    if (::sigaction(SIGXFSZ, nullptr, &old) == 0 && old.sa_handler == SIG_DFL) std::signal(SIGXFSZ, SIG_IGN);
  });
}

}  // namespace

// Named (not anonymous) so that OutputBatch::Pending can hold them.
namespace atomic_file_detail {

struct TempRegistration {
  explicit TempRegistration(const std::string& p) {
    if (p.size() >= PATH_MAX) return;  // cannot be longer: mkstemp's path fits PATH_MAX
    for (int i = 0; i < kTempSlots; ++i)
      if (!g_temp_live[i].load()) {
        std::memcpy(g_temp_path[i], p.c_str(), p.size() + 1);
        g_temp_live[i].store(true);
        slot = i;
        return;
      }
  }
  ~TempRegistration() {
    if (slot >= 0) g_temp_live[slot].store(false);
  }
  TempRegistration(const TempRegistration&) = delete;
  TempRegistration& operator=(const TempRegistration&) = delete;
  TempRegistration(TempRegistration&& o) noexcept : slot(o.slot) { o.slot = -1; }
  int slot = -1;
};

// A file written and synced under its temporary name, waiting for its batch's commit.
struct PendingRename {
  std::string tmp;
  fs::path target, path, dir;
  TempRegistration registered;
};
}  // namespace atomic_file_detail

namespace {
using atomic_file_detail::PendingRename;
using atomic_file_detail::TempRegistration;

// The open batch's files (OutputBatch), or none: write_file_atomic renames at once.
thread_local std::vector<PendingRename>* g_batch = nullptr;

void rename_into_place(const std::string& tmp, const fs::path& target, const fs::path& path, const fs::path& dir) {
  if (::rename(tmp.c_str(), target.c_str()) != 0) {
    const int err = errno;
    ::unlink(tmp.c_str());
    fail(path, "rename failed", err);
  }
  const int dfd = ::open(dir.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (dfd >= 0) {  // best effort: some file systems refuse fsync on directories
    (void)::fsync(dfd);
    ::close(dfd);
  }
}

// Files read as input, by (device, inode): note_input_file / write_file_atomic.
// The change time is part of the key: a file read, deleted and replaced by a new one (an
// inode number reused) is not the input any more.
std::mutex g_inputs_mutex;
using InputKey = std::tuple<dev_t, ino_t, time_t, long>;
std::set<InputKey> g_inputs;
InputKey input_key(const struct stat& st) { return {st.st_dev, st.st_ino, st.st_ctim.tv_sec, st.st_ctim.tv_nsec}; }

// The file a path finally names after its symlinks (relative links resolve against the
// link's folder). A dangling link names the file it would create.
fs::path follow_links(const fs::path& path) {
  fs::path p = path;
  for (int hops = 0;; ++hops) {
    struct stat st {};
    if (::lstat(p.c_str(), &st) != 0 || !S_ISLNK(st.st_mode)) return p;
    if (hops == 40) fail(path, "too many levels of symbolic links", ELOOP);
    std::error_code ec;
    const fs::path target = fs::read_symlink(p, ec);
    if (ec) fail(path, "cannot read the symbolic link", ec.value());
    p = target.is_absolute() ? target : p.parent_path() / target;
  }
}

void write_all(int fd, std::string_view contents, const std::function<void(const char*)>& on_error) {
  const char* p = contents.data();
  std::size_t left = contents.size();
  while (left > 0) {
    const ssize_t n = ::write(fd, p, left);
    if (n < 0) {
      if (errno == EINTR) continue;
      on_error("write failed");
    }
    if (n == 0) {
      errno = ENOSPC;
      on_error("write failed");
    }
    p += n;
    left -= static_cast<std::size_t>(n);
  }
}

}  // namespace

void note_input_file(const fs::path& path) {
  struct stat st {};
  if (::stat(path.c_str(), &st) != 0) return;
  const std::lock_guard<std::mutex> lock(g_inputs_mutex);
  g_inputs.insert(input_key(st));
}

namespace {
// A file someone made read-only: no write bit at all (root may write anything, but a
// chmod a-w still says "keep this"), or none for us.
bool read_only(const fs::path& file, const struct stat& st) {
  return (st.st_mode & (S_IWUSR | S_IWGRP | S_IWOTH)) == 0 || ::access(file.c_str(), W_OK) != 0;
}
}  // namespace

void write_file_atomic(const fs::path& path, std::string_view contents, OverInput over_input) {
  if (path.empty()) throw InputError("cannot write a file with an empty name");
  const fs::path target = follow_links(path);
  struct stat st {};
  const bool exists = ::stat(target.c_str(), &st) == 0;
  mode_t mode = 0644;
  if (exists && over_input == OverInput::Refuse && !S_ISCHR(st.st_mode)) {
    const std::lock_guard<std::mutex> lock(g_inputs_mutex);
    if (g_inputs.count(input_key(st)) != 0)
      fail(path, "it is an input file of this command (a scenario, world, mesh, material library or course it read); "
                 "refusing to overwrite it",
           0);
  }
  if (exists) {
    if (S_ISDIR(st.st_mode)) fail(path, "it is a directory", 0);
    if (S_ISREG(st.st_mode) && read_only(target, st)) fail(path, "it is read-only (no write permission): not replaced", 0);
    if (S_ISCHR(st.st_mode)) {
      // A device is written in place (replacing /dev/null with a file would be a disaster).
      const int fd = ::open(target.c_str(), O_WRONLY | O_NOCTTY | O_CLOEXEC);
      if (fd < 0) fail(path, "cannot open the device", errno);
      write_all(fd, contents, [&](const char* what) {
        const int err = errno;
        ::close(fd);
        fail(path, what, err);
      });
      if (::close(fd) != 0) fail(path, "close failed", errno);
      return;
    }
    if (!S_ISREG(st.st_mode)) fail(path, "not a regular file (a FIFO, socket or block device): refusing to replace it", 0);
    mode = st.st_mode & 07777;
  }
  const fs::path dir = target.has_parent_path() ? target.parent_path() : fs::path(".");
  std::string leaf = ".";  // hidden temporary: ".NAME.tmpXXXXXX"
  leaf += target.filename().string();
  leaf += ".tmpXXXXXX";
  const std::string tmpl = (dir / leaf).string();
  std::vector<char> name(tmpl.begin(), tmpl.end());
  name.push_back('\0');
  if (std::error_code ec; !fs::is_directory(dir, ec)) fail(path, "the folder '" + dir.string() + "' does not exist", 0);
  // A read-only file is not ours to replace (rename would, the folder being writable).
  if (exists && ::access(target.c_str(), W_OK) != 0) fail(path, "the file is read-only", errno);
  install_cleanup_handlers();
  const int fd = ::mkostemp(name.data(), O_CLOEXEC);
  if (fd < 0) fail(path, "cannot create a temporary file in '" + dir.string() + "'", errno);
  const std::string tmp(name.data());
  TempRegistration registered(tmp);

  auto abandon = [&](const char* what) {
    const int err = errno;
    ::close(fd);
    ::unlink(tmp.c_str());
    fail(path, what, err);
  };
  write_all(fd, contents, abandon);
  if (::fchmod(fd, mode) != 0) abandon("chmod failed");
  if (::fsync(fd) != 0) abandon("fsync failed");
  if (::close(fd) != 0) {
    const int err = errno;
    ::unlink(tmp.c_str());
    fail(path, "close failed", err);
  }
  if (g_batch != nullptr) {
    g_batch->push_back({tmp, target, path, dir, std::move(registered)});
    return;
  }
  rename_into_place(tmp, target, path, dir);
}

struct OutputBatch::Pending {
  std::vector<PendingRename> files;
};

OutputBatch::OutputBatch() : pending_(std::make_unique<Pending>()) {
  if (g_batch != nullptr) throw std::logic_error("OutputBatch: one batch at a time");
  g_batch = &pending_->files;
}

OutputBatch::~OutputBatch() {
  if (g_batch == &pending_->files) g_batch = nullptr;
  for (const PendingRename& p : pending_->files) ::unlink(p.tmp.c_str());  // not committed: none replaced
}

void OutputBatch::commit() {
  g_batch = nullptr;
  std::vector<PendingRename> files = std::move(pending_->files);
  pending_->files.clear();
  for (std::size_t i = 0; i < files.size(); ++i) {
    try {
      rename_into_place(files[i].tmp, files[i].target, files[i].path, files[i].dir);
    } catch (...) {
      for (std::size_t k = i + 1; k < files.size(); ++k) ::unlink(files[k].tmp.c_str());
      throw;
    }
  }
}

void refuse_output_over_input(const fs::path& output, const fs::path& input, const char* flag) {
  std::error_code ec;
  if (fs::equivalent(output, input, ec) && !ec)
    throw InputError(std::string(flag) + " " + output.string() + " is the input file " + input.string() +
                     ": refusing to overwrite it");
}

void check_output_path(const fs::path& path, const char* flag) {
  const std::string where = std::string(flag) + " " + path.string();
  const fs::path target = follow_links(path);
  struct stat st {};
  if (::stat(target.c_str(), &st) == 0) {
    if (S_ISDIR(st.st_mode)) throw InputError(where + ": it is a directory");
    if (!S_ISREG(st.st_mode) && !S_ISCHR(st.st_mode))
      throw InputError(where + ": not a regular file (a FIFO, socket or block device)");
    if (S_ISREG(st.st_mode) && read_only(target, st))
      throw InputError(where + ": it is read-only (no write permission): not replaced");
  }
  const fs::path dir = target.has_parent_path() ? target.parent_path() : fs::path(".");
  if (std::error_code ec; !fs::is_directory(dir, ec))
    throw InputError(where + ": the folder '" + dir.string() + "' does not exist");
}

bool same_output_file(const fs::path& a, const fs::path& b) {
  std::error_code ec;
  if (fs::equivalent(a, b, ec) && !ec) return true;  // both exist: same inode
  // Not both existing: compare the names the files would get, symlinks followed and the
  // folders made canonical ("./x" and "x", "d/../x").
  const auto final_name = [](const fs::path& p) {
    std::error_code e;
    // Absolute first: weakly_canonical keeps a relative name whose first part does not
    // exist as it is ("X" against "./X").
    const fs::path t = fs::absolute(follow_links(p), e);
    const fs::path c = fs::weakly_canonical(t, e);
    return (e ? fs::absolute(t, e) : c).lexically_normal();
  };
  return final_name(a) == final_name(b);
}

}  // namespace sweetspot
