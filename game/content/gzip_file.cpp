#include "game/content/gzip_file.hpp"

#include <zlib.h>

#include "game/content/toml_file.hpp"
#include "physics/error.hpp"

namespace sweetspot {
namespace {

// zlib's window bits for a gzip header and trailer (zlib.h, deflateInit2/inflateInit2: 16 +
// the 15-bit window).
constexpr int kGzipWindow = 16 + 15;

}  // namespace

bool is_gzip_path(const std::filesystem::path& path) { return path.extension() == ".gz"; }

std::filesystem::path without_gzip_suffix(const std::filesystem::path& path) {
  if (!is_gzip_path(path)) return path;
  std::filesystem::path p = path;
  return p.replace_extension();
}

std::string read_gzip_file(const std::filesystem::path& path, std::string_view what, std::uintmax_t max_bytes) {
  const std::string packed = read_data_file(path, what, max_bytes);
  z_stream z{};
  if (inflateInit2(&z, kGzipWindow) != Z_OK) throw InputError(path.string() + ": cannot start inflating the " + std::string(what));
  std::string out;
  z.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(packed.data()));
  z.avail_in = static_cast<uInt>(packed.size());
  int rc = Z_OK;
  char block[1 << 16];
  while (rc != Z_STREAM_END) {
    z.next_out = reinterpret_cast<Bytef*>(block);
    z.avail_out = sizeof block;
    rc = inflate(&z, Z_NO_FLUSH);
    if (rc != Z_OK && rc != Z_STREAM_END) {
      const std::string why = rc == Z_BUF_ERROR ? "the data ends early (truncated)"
                              : z.msg != nullptr ? std::string("not gzip data (") + z.msg + ")"
                                                 : "not gzip data";
      inflateEnd(&z);
      throw InputError(path.string() + ": cannot inflate the " + std::string(what) + ": " + why);
    }
    out.append(block, sizeof block - z.avail_out);
    if (out.size() > max_bytes) {
      inflateEnd(&z);
      throw InputError(path.string() + ": the " + std::string(what) + " inflates to more than " +
                       std::to_string(max_bytes) + " bytes (the limit)");
    }
  }
  inflateEnd(&z);
  return out;
}

std::string gzip_bytes(std::string_view bytes) {
  z_stream z{};
  if (deflateInit2(&z, Z_BEST_COMPRESSION, Z_DEFLATED, kGzipWindow, 9, Z_DEFAULT_STRATEGY) != Z_OK)
    throw std::runtime_error("gzip: cannot start deflating");
  std::string out(deflateBound(&z, static_cast<uLong>(bytes.size())) + 32, '\0');
  z.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(bytes.data()));
  z.avail_in = static_cast<uInt>(bytes.size());
  z.next_out = reinterpret_cast<Bytef*>(out.data());
  z.avail_out = static_cast<uInt>(out.size());
  const int rc = deflate(&z, Z_FINISH);
  out.resize(out.size() - z.avail_out);
  deflateEnd(&z);
  if (rc != Z_STREAM_END) throw std::runtime_error("gzip: deflate did not finish");
  return out;
}

}  // namespace sweetspot
