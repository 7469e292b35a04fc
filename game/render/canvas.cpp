#include "game/render/canvas.hpp"

#include <algorithm>
#include <cmath>
#include <memory>

#include <imgui.h>

#include "game/render/image.hpp"

namespace sweetspot {
namespace {

/// ImGui's default font baked once into an 8-bit coverage atlas; ImFontAtlas needs no
/// ImGui context. Thread-safe first use (a function-local static).
struct BitmapFont {
  ImFontAtlas atlas;
  const ImFont* font = nullptr;
  unsigned char* pixels = nullptr;
  int width = 0, height = 0;
  float line_height = 0;  // px from the top of a line to the lowest ink of any ASCII glyph
  BitmapFont() {
    font = atlas.AddFontDefault();
    atlas.GetTexDataAsAlpha8(&pixels, &width, &height);
    line_height = font->FontSize;
    for (int ch = 32; ch < 127; ++ch)
      if (const ImFontGlyph* g = font->FindGlyph(static_cast<ImWchar>(ch))) line_height = std::max(line_height, g->Y1);
  }
  const ImFontGlyph* glyph(char ch) const {
    const auto c = static_cast<unsigned char>(ch);
    return font->FindGlyph(static_cast<ImWchar>(c < 0x80 ? c : '?'));
  }
};

const BitmapFont& bitmap_font() {
  static const BitmapFont f;
  return f;
}

Rgb blend(const std::uint8_t* p, Rgb c, int alpha) {
  const auto mix = [&](int shift, int i) { return (((c >> shift) & 0xFF) * alpha + p[i] * (255 - alpha)) / 255; };
  return static_cast<Rgb>((mix(16, 0) << 16) | (mix(8, 1) << 8) | mix(0, 2));
}

}  // namespace

Canvas::Canvas(int width, int height, Rgb background)
    : width_(width), height_(height), rgba_(static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 4) {
  rect(0, 0, width, height, background);
}

void Canvas::put(int x, int y, Rgb c) {
  if (x < 0 || y < 0 || x >= width_ || y >= height_) return;
  std::uint8_t* p = rgba_.data() + (static_cast<std::size_t>(y) * static_cast<std::size_t>(width_) + static_cast<std::size_t>(x)) * 4;
  p[0] = static_cast<std::uint8_t>(c >> 16);
  p[1] = static_cast<std::uint8_t>(c >> 8);
  p[2] = static_cast<std::uint8_t>(c);
  p[3] = 255;
}

void Canvas::rect(int x0, int y0, int x1, int y1, Rgb c) {
  for (int y = y0; y < y1; ++y)
    for (int x = x0; x < x1; ++x) put(x, y, c);
}

void Canvas::disc(double cx, double cy, double r, Rgb c) {
  for (int y = static_cast<int>(std::floor(cy - r)); y <= static_cast<int>(std::ceil(cy + r)); ++y)
    for (int x = static_cast<int>(std::floor(cx - r)); x <= static_cast<int>(std::ceil(cx + r)); ++x)
      if ((x - cx) * (x - cx) + (y - cy) * (y - cy) <= r * r) put(x, y, c);
}

void Canvas::marker(double cx, double cy, double outer, double inner, Rgb fill, Rgb ring) {
  disc(cx, cy, outer, ring);
  disc(cx, cy, inner, fill);
}

void Canvas::line(double x0, double y0, double x1, double y1, Rgb c, double half_width) {
  const int n = static_cast<int>(std::hypot(x1 - x0, y1 - y0)) + 1;
  for (int i = 0; i <= n; ++i) disc(x0 + (x1 - x0) * i / n, y0 + (y1 - y0) * i / n, half_width, c);
}

int Canvas::text(int x, int y, std::string_view s, Rgb c, int scale) {
  const BitmapFont& f = bitmap_font();
  double pen = x;
  for (const char ch : s) {
    const ImFontGlyph* g = f.glyph(ch);
    if (g == nullptr) continue;
    const int gw = static_cast<int>(std::lround((g->U1 - g->U0) * f.width));
    const int gh = static_cast<int>(std::lround((g->V1 - g->V0) * f.height));
    const int u0 = static_cast<int>(std::lround(g->U0 * f.width));
    const int v0 = static_cast<int>(std::lround(g->V0 * f.height));
    for (int j = 0; j < gh; ++j)
      for (int i = 0; i < gw; ++i) {
        const int a = f.pixels[(v0 + j) * f.width + u0 + i];
        if (a == 0) continue;
        for (int sy = 0; sy < scale; ++sy)
          for (int sx = 0; sx < scale; ++sx) {
            const int px = static_cast<int>(pen + g->X0 * scale) + i * scale + sx;
            const int py = y + static_cast<int>(g->Y0 * scale) + j * scale + sy;
            if (px < 0 || py < 0 || px >= width_ || py >= height_) continue;
            const std::uint8_t* p = rgba_.data() + (static_cast<std::size_t>(py) * static_cast<std::size_t>(width_) + static_cast<std::size_t>(px)) * 4;
            put(px, py, blend(p, c, a));
          }
      }
    pen += g->AdvanceX * scale;
  }
  return static_cast<int>(pen) - x;
}

int Canvas::text_width(std::string_view s, int scale) {
  const BitmapFont& f = bitmap_font();
  double w = 0;
  for (const char ch : s)
    if (const ImFontGlyph* g = f.glyph(ch)) w += g->AdvanceX * scale;
  return static_cast<int>(std::ceil(w));
}

int Canvas::text_height(int scale) { return static_cast<int>(std::ceil(bitmap_font().line_height)) * scale; }

void Canvas::write_png(const std::filesystem::path& path) const { write_png_atomic(path, width_, height_, rgba_); }

}  // namespace sweetspot
