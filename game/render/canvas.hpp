// A CPU drawing surface for charts written as PNG without GL (spray charts, sweep heatmaps):
// filled rectangles, discs, thick lines and text. Text uses Dear ImGui's built-in bitmap
// font (ProggyClean, 13 px) baked on the CPU, so charts need no font file and no context.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string_view>
#include <vector>

namespace sweetspot {

/// 0xRRGGBB.
using Rgb = std::uint32_t;

class Canvas {
 public:
  Canvas(int width, int height, Rgb background = 0xFFFFFF);
  int width() const { return width_; }
  int height() const { return height_; }
  void put(int x, int y, Rgb c);
  void rect(int x0, int y0, int x1, int y1, Rgb c);  ///< filled, [x0, x1) × [y0, y1)
  void disc(double cx, double cy, double r, Rgb c);
  /// A chart marker: a disc of `fill` with radius `inner` inside a `ring` out to `outer`.
  void marker(double cx, double cy, double outer, double inner, Rgb fill, Rgb ring = 0x000000);
  void line(double x0, double y0, double x1, double y1, Rgb c, double half_width = 1.5);
  /// Text with its top-left at (x, y), each font pixel drawn `scale` × `scale`; ASCII only
  /// (other bytes draw the font's fallback). Returns the width drawn, px.
  int text(int x, int y, std::string_view s, Rgb c, int scale = 1);
  /// Width and height `s` would take, px.
  static int text_width(std::string_view s, int scale = 1);
  static int text_height(int scale = 1);
  /// Writes the canvas as a PNG atomically (write_png_atomic).
  void write_png(const std::filesystem::path& path) const;

 private:
  int width_, height_;
  std::vector<std::uint8_t> rgba_;
};

}  // namespace sweetspot
