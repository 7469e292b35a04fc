// Atomic file output: a reader (or a crash) never sees a half-written file. Every file the
// CLI writes (CSV, updated regression cases, PNGs) goes through here.
#pragma once

#include <filesystem>
#include <string_view>

namespace sweetspot {

/// Writes `contents` to `path` atomically: a temporary file in the same directory is
/// written, flushed to disk (fsync) and renamed over `path`, so `path` holds either the old
/// contents or the new ones, never a mix. On failure the temporary file is removed, `path`
/// is untouched, and InputError names `path` and the reason (missing directory, no
/// permission, disk full).
void write_file_atomic(const std::filesystem::path& path, std::string_view contents);

}  // namespace sweetspot
