// write_file_atomic: mkstemp next to the target (rename is atomic only within one file
// system), write everything, fsync the file, rename, then fsync the directory so the new
// name survives a power loss too.
#include "game/util/atomic_file.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <string>
#include <vector>

#include "physics/error.hpp"

namespace sweetspot {
namespace {

[[noreturn]] void fail(const std::filesystem::path& path, const std::string& what, int err) {
  throw InputError("cannot write '" + path.string() + "': " + what + ": " + std::strerror(err));
}

}  // namespace

void write_file_atomic(const std::filesystem::path& path, std::string_view contents) {
  if (path.empty()) throw InputError("cannot write a file with an empty name");
  if (std::filesystem::is_directory(path)) {
    throw InputError("cannot write '" + path.string() + "': it is a directory");
  }
  const std::filesystem::path dir = path.has_parent_path() ? path.parent_path() : ".";
  std::string leaf = ".";  // hidden temporary: ".NAME.tmpXXXXXX"
  leaf += path.filename().string();
  leaf += ".tmpXXXXXX";
  const std::string tmpl = (dir / leaf).string();
  std::vector<char> name(tmpl.begin(), tmpl.end());
  name.push_back('\0');
  const int fd = ::mkstemp(name.data());
  if (fd < 0) fail(path, "cannot create a temporary file in '" + dir.string() + "'", errno);
  const std::string tmp(name.data());

  auto abandon = [&](const std::string& what) {
    const int err = errno;
    ::close(fd);
    ::unlink(tmp.c_str());
    fail(path, what, err);
  };
  const char* p = contents.data();
  std::size_t left = contents.size();
  while (left > 0) {
    const ssize_t n = ::write(fd, p, left);
    if (n < 0) {
      if (errno == EINTR) continue;
      abandon("write failed");
    }
    p += n;
    left -= static_cast<std::size_t>(n);
  }
  // mkstemp creates 0600; outputs are meant to be shared, so rw-r--r-- (reading the umask
  // would mean setting it, which is not thread-safe).
  if (::fchmod(fd, 0644) != 0) abandon("chmod failed");
  if (::fsync(fd) != 0) abandon("fsync failed");
  if (::close(fd) != 0) {
    const int err = errno;
    ::unlink(tmp.c_str());
    fail(path, "close failed", err);
  }
  if (::rename(tmp.c_str(), path.c_str()) != 0) {
    const int err = errno;
    ::unlink(tmp.c_str());
    fail(path, "rename failed", err);
  }
  const int dfd = ::open(dir.c_str(), O_RDONLY | O_DIRECTORY);
  if (dfd >= 0) {  // best effort: some file systems refuse fsync on directories
    (void)::fsync(dfd);
    ::close(dfd);
  }
}

}  // namespace sweetspot
