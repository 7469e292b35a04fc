#include "game/render/dispersion_plot.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "game/render/canvas.hpp"

namespace sweetspot {
namespace {

constexpr int kWidth = 900, kHeight = 800;
constexpr Rgb kInk = 0x222222;

/// Distinct colours for up to 12 clubs (Okabe–Ito first, then darker variants).
constexpr Rgb kClubColours[] = {0xE69F00, 0x56B4E9, 0x009E73, 0xF0E442, 0x0072B2, 0xD55E00,
                                0xCC79A7, 0x000000, 0x8C564B, 0x7F7F7F, 0x17BECF, 0xBCBD22};

std::string fmt(double v) {
  char b[32];
  std::snprintf(b, sizeof b, "%.0f", v);
  return b;
}

}  // namespace

void write_dispersion_plot(const std::vector<StrokeRecord>& strokes, const std::string& title, const DisplayUnits& u,
                           const std::filesystem::path& png) {
  std::vector<const StrokeRecord*> full;
  std::vector<std::string> clubs;  // in order of first use
  for (const StrokeRecord& s : strokes) {
    if (s.lie == "green" || s.club == "putter" || !std::isfinite(s.carry_m) || !std::isfinite(s.side_m)) continue;
    full.push_back(&s);
    if (std::find(clubs.begin(), clubs.end(), s.club) == clubs.end()) clubs.push_back(s.club);
  }
  Canvas c(kWidth, kHeight, 0xFFFFFF);
  c.text(20, 14, title + ": " + std::to_string(full.size()) + " strokes off the green, carry vs side of the aim line (" +
                     u.distance_unit() + ")", kInk);
  const int x0 = 90, y0 = 50, x1 = 700, y1 = 740;
  c.rect(x0, y0, x1, y1, 0x7FB36A);  // fairway-ish backdrop
  double carry_max = 10.0, side_max = 5.0;
  for (const auto* s : full) {
    carry_max = std::max(carry_max, u.dist(s->carry_m));
    side_max = std::max(side_max, std::fabs(u.dist(s->side_m)));
  }
  carry_max *= 1.08;
  side_max = std::max(side_max * 1.15, 0.1 * carry_max);
  const auto X = [&](double side) { return x0 + (side + side_max) / (2 * side_max) * (x1 - x0); };
  const auto Y = [&](double carry) { return y1 - carry / carry_max * (y1 - y0); };
  // The aim line and a ring every 50 (yd or m) of carry.
  c.rect(static_cast<int>(X(0)), y0, static_cast<int>(X(0)) + 2, y1, 0xF5F5F5);
  for (double d = 50; d < carry_max; d += 50) {
    c.rect(x0, static_cast<int>(Y(d)), x1, static_cast<int>(Y(d)) + 1, 0x9CC98A);
    c.text(x0 - 8 - Canvas::text_width(fmt(d)), static_cast<int>(Y(d)) - 6, fmt(d), kInk);
  }
  for (const auto* s : full) {
    const auto k = static_cast<std::size_t>(std::find(clubs.begin(), clubs.end(), s->club) - clubs.begin());
    const double x = X(u.dist(s->side_m)), y = Y(u.dist(s->carry_m));
    c.marker(x, y, 6.0, 4.5, kClubColours[k % std::size(kClubColours)]);
  }
  c.text(x0, y1 + 8, fmt(-side_max) + " (left)", kInk);
  const std::string right = fmt(side_max) + " (right)";
  c.text(x1 - Canvas::text_width(right), y1 + 8, right, kInk);
  c.text((x0 + x1) / 2 - 30, y1 + 8, "aim line", kInk);
  // Legend: club, shots, mean carry and mean side (the bias a player would correct).
  int y = y0;
  for (std::size_t k = 0; k < clubs.size(); ++k) {
    double carry = 0, side = 0;
    int n = 0;
    for (const auto* s : full)
      if (s->club == clubs[k]) carry += u.dist(s->carry_m), side += u.dist(s->side_m), ++n;
    c.marker(x1 + 22, y + 6, 6.0, 4.5, kClubColours[k % std::size(kClubColours)]);
    c.text(x1 + 34, y, clubs[k] + " x" + std::to_string(n), kInk);
    char b[64];
    std::snprintf(b, sizeof b, "%.0f, %+.1f", carry / n, side / n);
    c.text(x1 + 34, y + 14, b, 0x555555);
    y += 34;
  }
  c.text(x1 + 14, y + 6, "mean carry, side", 0x555555);
  c.write_png(png);
}

}  // namespace sweetspot
