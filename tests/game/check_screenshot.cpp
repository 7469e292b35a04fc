// check_screenshot FILE WIDTH HEIGHT [MIN_COLOURS]: exits 0 when FILE is a PNG of that size that shows a
// real frame (many colours, not one flat fill), 1 otherwise with the reason. Used by the
// Xvfb game test so CI needs no image tools beyond the project's own dependencies.
#include <cstdio>
#include <cstdlib>
#include <set>

#define STB_IMAGE_STATIC
#define STB_IMAGE_IMPLEMENTATION
#include <stb_image.h>

int main(int argc, char** argv) {
  if (argc != 4 && argc != 5) {
    std::fprintf(stderr, "usage: check_screenshot FILE WIDTH HEIGHT [MIN_COLOURS]\n");
    return 2;
  }
  int w = 0, h = 0, n = 0;
  unsigned char* px = stbi_load(argv[1], &w, &h, &n, 4);
  if (!px) {
    std::fprintf(stderr, "%s: not a readable PNG (%s)\n", argv[1], stbi_failure_reason());
    return 1;
  }
  const int want_w = std::atoi(argv[2]), want_h = std::atoi(argv[3]);
  int rc = 0;
  if (w != want_w || h != want_h) {
    std::fprintf(stderr, "%s: %dx%d, expected %dx%d\n", argv[1], w, h, want_w, want_h);
    rc = 1;
  }
  // A rendered scene with panels has hundreds of colours even at 5 bits per channel (the
  // quantisation keeps noise from counting); a blank or clear-only frame has one or two.
  const std::size_t min_colours = argc == 5 ? static_cast<std::size_t>(std::atol(argv[4])) : 200;
  std::set<unsigned> colours;
  for (long i = 0; i < static_cast<long>(w) * h; ++i) {
    const unsigned char* p = px + 4 * i;
    colours.insert((p[0] >> 3) << 10 | (p[1] >> 3) << 5 | (p[2] >> 3));
  }
  if (colours.size() < min_colours) {
    std::fprintf(stderr, "%s: only %zu distinct colours, the frame looks empty\n", argv[1], colours.size());
    rc = 1;
  }
  std::printf("%s: %dx%d, %zu distinct colours\n", argv[1], w, h, colours.size());
  stbi_image_free(px);
  return rc;
}
