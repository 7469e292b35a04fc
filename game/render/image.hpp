// Images out of the renderer: row flipping (GL reads bottom-up) and atomic PNG writing.
#pragma once

#include <cstdint>
#include <filesystem>
#include <vector>

namespace sweetspot {

/// Reverses the row order of a tightly packed width x height image of `channels` bytes per
/// pixel, in place.
void flip_rows(std::vector<std::uint8_t>& pixels, int width, int height, int channels);

/// Writes RGBA8 pixels (top row first) as a PNG: to a temporary file in the same folder,
/// then renamed over `path`, so readers never see a half-written image. Throws InputError
/// naming the path when it cannot be written (missing folder, permissions) or when the
/// buffer size does not match width x height x 4.
/// Checks before a run that `path` can take a PNG later: check_output_path, and a name
/// that ends in .png (any case) unless it is a character device (/dev/null): an image
/// written under "shot.jpg" or "grid.csv" would be a PNG by another name. InputError
/// naming `flag`.
void check_png_output(const std::filesystem::path& path, const char* flag);

void write_png_atomic(const std::filesystem::path& path, int width, int height, const std::vector<std::uint8_t>& rgba);

/// Reads a PNG as RGBA8 (top row first); throws InputError naming the path on failure.
std::vector<std::uint8_t> read_png_rgba(const std::filesystem::path& path, int* width, int* height);

}  // namespace sweetspot
