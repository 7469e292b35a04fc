#include "game/render/image.hpp"

#include <sys/stat.h>

#include <cctype>

#include <algorithm>
#include <cstdio>
#include <string>
#include <system_error>

#include <stb/stb_image.h>
#include <stb/stb_image_write.h>

#include "game/util/atomic_file.hpp"
#include "physics/error.hpp"

namespace sweetspot {

void flip_rows(std::vector<std::uint8_t>& pixels, int width, int height, int channels) {
  const auto row = static_cast<std::size_t>(width) * static_cast<std::size_t>(channels);
  for (int y = 0; y < height / 2; ++y) {
    auto a = pixels.begin() + static_cast<std::ptrdiff_t>(row * static_cast<std::size_t>(y));
    auto b = pixels.begin() + static_cast<std::ptrdiff_t>(row * static_cast<std::size_t>(height - 1 - y));
    std::swap_ranges(a, a + static_cast<std::ptrdiff_t>(row), b);
  }
}

namespace {

bool names_png(const std::filesystem::path& path) {
  std::string ext = path.extension().string();
  for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  if (ext == ".png") return true;
  struct stat st {};
  return ::stat(path.c_str(), &st) == 0 && S_ISCHR(st.st_mode);  // /dev/null, /dev/stdout
}

}  // namespace

void check_png_output(const std::filesystem::path& path, const char* flag) {
  check_output_path(path, flag);
  if (!names_png(path)) throw InputError(std::string(flag) + " " + path.string() + ": the image is a PNG; name it FILE.png");
}

void write_png_atomic(const std::filesystem::path& path, int width, int height, const std::vector<std::uint8_t>& rgba) {
  if (!names_png(path)) throw InputError("cannot write " + path.string() + ": the image is a PNG; name it FILE.png");
  if (width <= 0 || height <= 0 || rgba.size() != static_cast<std::size_t>(width) * height * 4) {
    throw InputError("PNG " + path.string() + ": pixel buffer does not match " + std::to_string(width) + "x" +
                     std::to_string(height) + " RGBA");
  }
  // Encoded in memory, then written by the one atomic writer (exclusive temporary, every
  // write checked, the old file kept on failure).
  std::string png;
  const auto append = [](void* context, void* data, int size) {
    static_cast<std::string*>(context)->append(static_cast<const char*>(data), static_cast<std::size_t>(size));
  };
  if (stbi_write_png_to_func(append, &png, width, height, 4, rgba.data(), width * 4) == 0 || png.empty())
    throw InputError("cannot write " + path.string() + ": PNG encoding failed");
  write_file_atomic(path, png);
}

std::vector<std::uint8_t> read_png_rgba(const std::filesystem::path& path, int* width, int* height) {
  int w = 0, h = 0, n = 0;
  stbi_uc* data = stbi_load(path.c_str(), &w, &h, &n, 4);
  if (data == nullptr) throw InputError("cannot read PNG " + path.string() + ": " + stbi_failure_reason());
  std::vector<std::uint8_t> out(data, data + static_cast<std::size_t>(w) * h * 4);
  stbi_image_free(data);
  *width = w;
  *height = h;
  return out;
}

}  // namespace sweetspot
