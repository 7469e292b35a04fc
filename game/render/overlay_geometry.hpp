// Unlit marker geometry laid into the scene: rings on the ground, pins, flat ground
// stripes and billboard labels in a 5x7 bitmap font. Pure geometry; sizes are given in
// metres, so callers scale them by Camera::metres_per_pixel for a screen-constant look.
#pragma once

#include <string_view>

#include <Eigen/Core>

#include "game/render/mesh_data.hpp"
#include "physics/math.hpp"

namespace sweetspot {

/// Flat ring (annulus) in the horizontal plane at `centre`.
void append_ring(MeshData& out, const Vec3& centre, double r_inner, double r_outer, const Eigen::Vector3f& color,
                 int segments = 40);

/// Vertical pin from `base` up `height`, `width` wide, facing the camera (billboarded about y).
void append_pin(MeshData& out, const Vec3& base, double height, double width, const Vec3& camera_right,
                const Eigen::Vector3f& color);

/// A straight band of `width` between a and b, in the plane containing a-b and `normal`.
void append_band(MeshData& out, const Vec3& a, const Vec3& b, double width, const Vec3& normal,
                 const Eigen::Vector3f& color);

/// True if the 5x7 font has a glyph for c (digits, a few lower-case letters, space, '.').
bool font_has_glyph(char c);

/// Rows of the font's cell below the baseline (g, p, y hang into them).
inline constexpr int kDescentRows = 2;

/// Text drawn as one quad per lit font cell, `height` metres tall (cap height), standing on
/// the baseline through `origin` (its left end) and running along `right`, with `up` as the
/// glyph's up; descenders reach text_descent(height) below it. Unknown characters draw as
/// blanks. Returns the text width in metres.
double append_text(MeshData& out, std::string_view text, const Vec3& origin, const Vec3& right, const Vec3& up,
                   double height, const Eigen::Vector3f& color);

/// How far below the baseline append_text's descenders reach, in the units of `height`.
double text_descent(double height);

/// Width in metres append_text would use.
double text_width(std::string_view text, double height);

}  // namespace sweetspot
