// Atomic file output: a reader (or a crash) never sees a half-written file. Every file the
// program writes (CSV, PNG, updated regression cases, saved scenarios, sessions) goes
// through here.
#pragma once

#include <filesystem>
#include <memory>
#include <string_view>

namespace sweetspot {

/// Writes `contents` to `path` atomically: an exclusive temporary file with an unpredictable
/// name (mkstemp: O_EXCL, so a planted symlink cannot redirect it) in the same directory is
/// written (every write checked), flushed to disk (fsync), closed (checked) and renamed over
/// the target, so the target holds either the old contents or the new ones, never a mix.
///  - A symlink is followed (to depth 40): the file it names is replaced, the link stays.
///  - An existing file keeps its permission bits; a new one is rw-r--r--. The rename gives
///    it a new inode, so another hard link to the old file keeps the old contents (the
///    price of never showing a half-written file; the old inode is what such a link named).
///    Owner and extended attributes are not carried over either.
///  - A character device (/dev/null, /dev/stdout, a tty) is written directly, never replaced;
///    a FIFO, socket or block device is refused (a FIFO would block, the others are not files).
///  - On any failure the temporary file is removed and the target untouched; so is it when
///    SIGINT or SIGTERM arrives mid-write (the signal then ends the process as usual).
/// Throws InputError naming `path` and the reason (missing directory, no permission, disk
/// full, file-size limit).
/// Whether an output may replace a file this process read as input (note_input_file).
enum class OverInput : unsigned char {
  Refuse,  ///< every output: `render x.toml -o world.obj` must not destroy the world
  Allow,   ///< a command whose output is its input by design (regress --update, a session)
};
void write_file_atomic(const std::filesystem::path& path, std::string_view contents,
                       OverInput over_input = OverInput::Refuse);

/// A command's outputs replaced together: while a batch is open, write_file_atomic writes
/// and syncs each file under its temporary name but leaves the target alone; commit()
/// renames them all into place, and a batch closed without it (a later output failed)
/// removes them, so `render -o F.png --video F.mp4` that fails on the clip keeps the old
/// image too. One batch at a time, on the thread that opened it.
class OutputBatch {
 public:
  OutputBatch();
  ~OutputBatch();
  OutputBatch(const OutputBatch&) = delete;
  OutputBatch& operator=(const OutputBatch&) = delete;
  void commit();

 private:
  struct Pending;  ///< the files waiting for their rename (atomic_file.cpp)
  std::unique_ptr<Pending> pending_;
};

/// Notes a file the process reads (scenario, world, mesh, material library, course, case),
/// by device and inode, so that write_file_atomic can refuse to replace it, however the
/// output path names it (a symlink, a hard link, "./x"). Thread-safe.
void note_input_file(const std::filesystem::path& path);

/// Checks before a long run that `path` can be written later: its folder exists and it is
/// not a directory, FIFO, socket or block device. InputError naming `flag` otherwise.
void check_output_path(const std::filesystem::path& path, const char* flag);

/// True when two output paths name one file (after symlinks, dangling ones included, and
/// hard links), so writing both would lose one: `--csv x --plot link-to-x`.
bool same_output_file(const std::filesystem::path& a, const std::filesystem::path& b);

/// Refuses (InputError naming `flag`) an output that is the same file as `input` (after
/// symlinks and hard links): `render x.toml -o x.toml` must not destroy the scenario.
/// Nothing is checked when either does not exist yet.
void refuse_output_over_input(const std::filesystem::path& output, const std::filesystem::path& input,
                              const char* flag);

}  // namespace sweetspot
