#include "game/render/overlay_geometry.hpp"

#include <array>
#include <cmath>

namespace sweetspot {
namespace {

void push_quad(MeshData& out, const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d,
               const Eigen::Vector3f& color) {
  const auto base = static_cast<std::uint32_t>(out.vertices.size());
  for (const Vec3* q : {&a, &b, &c, &d}) {
    Vertex v;
    v.position = q->cast<float>();
    v.color = color;
    out.vertices.push_back(v);
  }
  for (std::uint32_t k : {0u, 1u, 2u, 0u, 2u, 3u}) out.indices.push_back(base + k);
}

constexpr int kCapRows = 7, kGlyphRows = kCapRows + kDescentRows;

struct Glyph {
  char c;
  // Top row first; bit 4 = leftmost column. Rows 0-6 stand on the baseline (capitals and
  // digits fill all seven, lower case rows 2-6); rows 7-8 hang below it, for descenders.
  std::array<std::uint8_t, kGlyphRows> rows;
};

// A 5x7 font drawn for this project, with two rows of descent: digits plus the letters
// the markers use.
constexpr std::array<Glyph, 36> kFont{{
    {'0', {0x0E, 0x11, 0x13, 0x15, 0x19, 0x11, 0x0E}},
    {'1', {0x04, 0x0C, 0x04, 0x04, 0x04, 0x04, 0x0E}},
    {'2', {0x0E, 0x11, 0x01, 0x02, 0x04, 0x08, 0x1F}},
    {'3', {0x1F, 0x02, 0x04, 0x02, 0x01, 0x11, 0x0E}},
    {'4', {0x02, 0x06, 0x0A, 0x12, 0x1F, 0x02, 0x02}},
    {'5', {0x1F, 0x10, 0x1E, 0x01, 0x01, 0x11, 0x0E}},
    {'6', {0x06, 0x08, 0x10, 0x1E, 0x11, 0x11, 0x0E}},
    {'7', {0x1F, 0x01, 0x02, 0x04, 0x08, 0x08, 0x08}},
    {'8', {0x0E, 0x11, 0x11, 0x0E, 0x11, 0x11, 0x0E}},
    {'9', {0x0E, 0x11, 0x11, 0x0F, 0x01, 0x02, 0x0C}},
    {'y', {0x00, 0x00, 0x11, 0x11, 0x11, 0x11, 0x0F, 0x01, 0x0E}},
    {'d', {0x01, 0x01, 0x0D, 0x13, 0x11, 0x11, 0x0F}},
    {'f', {0x06, 0x09, 0x08, 0x1C, 0x08, 0x08, 0x08}},
    {'t', {0x08, 0x08, 0x1C, 0x08, 0x08, 0x09, 0x06}},
    {'m', {0x00, 0x00, 0x1A, 0x15, 0x15, 0x11, 0x11}},
    {'c', {0x00, 0x00, 0x0E, 0x10, 0x10, 0x11, 0x0E}},
    {'a', {0x00, 0x00, 0x0E, 0x01, 0x0F, 0x11, 0x0F}},
    {'r', {0x00, 0x00, 0x16, 0x19, 0x10, 0x10, 0x10}},
    {'o', {0x00, 0x00, 0x0E, 0x11, 0x11, 0x11, 0x0E}},
    {'l', {0x0C, 0x04, 0x04, 0x04, 0x04, 0x04, 0x0E}},
    {'i', {0x04, 0x00, 0x0C, 0x04, 0x04, 0x04, 0x0E}},
    {'g', {0x00, 0x00, 0x0F, 0x11, 0x11, 0x11, 0x0F, 0x01, 0x0E}},
    {'h', {0x10, 0x10, 0x16, 0x19, 0x11, 0x11, 0x11}},
    {'b', {0x10, 0x10, 0x16, 0x19, 0x11, 0x11, 0x1E}},
    {'u', {0x00, 0x00, 0x11, 0x11, 0x11, 0x13, 0x0D}},
    {'n', {0x00, 0x00, 0x16, 0x19, 0x11, 0x11, 0x11}},
    {'e', {0x00, 0x00, 0x0E, 0x11, 0x1F, 0x10, 0x0E}},
    {'s', {0x00, 0x00, 0x0E, 0x10, 0x0E, 0x01, 0x1E}},
    {'p', {0x00, 0x00, 0x1E, 0x11, 0x11, 0x11, 0x1E, 0x10, 0x10}},
    {'w', {0x00, 0x00, 0x11, 0x11, 0x15, 0x15, 0x0A}},
    {'k', {0x10, 0x10, 0x12, 0x14, 0x18, 0x14, 0x12}},
    {'v', {0x00, 0x00, 0x11, 0x11, 0x11, 0x0A, 0x04}},
    {'x', {0x00, 0x00, 0x11, 0x0A, 0x04, 0x0A, 0x11}},
    {'-', {0x00, 0x00, 0x00, 0x1F, 0x00, 0x00, 0x00}},
    {'.', {0x00, 0x00, 0x00, 0x00, 0x00, 0x0C, 0x0C}},
    {' ', {0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00}},
}};

const Glyph* find_glyph(char c) {
  for (const auto& g : kFont) {
    if (g.c == c) return &g;
  }
  return nullptr;
}

}  // namespace

void append_ring(MeshData& out, const Vec3& centre, double r_inner, double r_outer, const Eigen::Vector3f& color,
                 int segments) {
  for (int i = 0; i < segments; ++i) {
    const double a0 = 2 * kPi * i / segments, a1 = 2 * kPi * (i + 1) / segments;
    const Vec3 d0(std::cos(a0), 0, std::sin(a0)), d1(std::cos(a1), 0, std::sin(a1));
    push_quad(out, centre + r_inner * d0, centre + r_outer * d0, centre + r_outer * d1, centre + r_inner * d1, color);
  }
}

void append_pin(MeshData& out, const Vec3& base, double height, double width, const Vec3& camera_right,
                const Eigen::Vector3f& color) {
  Vec3 side = camera_right;
  side.y() = 0;
  side = side.norm() > 1e-9 ? side.normalized() : Vec3::UnitZ();
  const Vec3 h = 0.5 * width * side, up(0, height, 0);
  push_quad(out, base - h, base + h, base + h + up, base - h + up, color);
}

void append_band(MeshData& out, const Vec3& a, const Vec3& b, double width, const Vec3& normal,
                 const Eigen::Vector3f& color) {
  Vec3 side = (b - a).cross(normal);
  if (side.norm() < 1e-12) return;
  side = side.normalized() * (0.5 * width);
  push_quad(out, a - side, b - side, b + side, a + side, color);
}

bool font_has_glyph(char c) { return find_glyph(c) != nullptr; }

double text_width(std::string_view text, double height) {
  const double cell = height / kCapRows;
  return text.empty() ? 0.0 : cell * (6.0 * static_cast<double>(text.size()) - 1.0);
}

double text_descent(double height) { return height * kDescentRows / kCapRows; }

double append_text(MeshData& out, std::string_view text, const Vec3& origin, const Vec3& right, const Vec3& up,
                   double height, const Eigen::Vector3f& color) {
  const double cell = height / kCapRows;
  const Vec3 r = right.normalized() * cell, u = up.normalized() * cell;
  for (std::size_t k = 0; k < text.size(); ++k) {
    const Glyph* g = find_glyph(text[k]);
    if (g == nullptr) continue;
    const Vec3 glyph_origin = origin + r * (6.0 * static_cast<double>(k));
    for (int row = 0; row < kGlyphRows; ++row) {
      for (int col = 0; col < 5; ++col) {
        if (((g->rows[static_cast<std::size_t>(row)] >> (4 - col)) & 1) == 0) continue;
        const Vec3 p = glyph_origin + r * col + u * (kCapRows - 1 - row);
        push_quad(out, p, p + r, p + r + u, p + u, color);
      }
    }
  }
  return text_width(text, height);
}

}  // namespace sweetspot
