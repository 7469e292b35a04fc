// Gzip-compressed data files: a large generated mesh (an imported course's ground) is kept
// compressed, ~4x smaller, and inflated in memory when it is read.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>

namespace sweetspot {

/// Whether `path` names gzip data ("world.obj.gz").
bool is_gzip_path(const std::filesystem::path& path);

/// The name with its ".gz" taken off ("world.obj.gz" -> "world.obj").
std::filesystem::path without_gzip_suffix(const std::filesystem::path& path);

/// The inflated bytes of the gzip file `path`: the file at most `max_bytes` as stored, and
/// at most `max_bytes` inflated (a small file that inflates without end is refused as it
/// passes the limit). Throws InputError naming the path: the read_data_file refusals, data
/// that is not gzip, a truncated or corrupt stream, an inflated size over the limit.
std::string read_gzip_file(const std::filesystem::path& path, std::string_view what, std::uintmax_t max_bytes);

/// `bytes` gzip-compressed at zlib's best level (course import writes its mesh this way).
std::string gzip_bytes(std::string_view bytes);

}  // namespace sweetspot
