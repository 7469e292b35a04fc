#include "game/render/sweep_plot.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <functional>
#include <limits>

#include "game/render/canvas.hpp"
#include "physics/units.hpp"

namespace sweetspot {
namespace {

constexpr int kWidth = 1200, kHeight = 940;
constexpr Rgb kInk = 0x222222, kGrid = 0xDDDDDD;

/// Viridis-like ramp (dark blue → green → yellow): ordered in lightness, readable in grey
/// and by most colour-blind readers. t in [0, 1].
Rgb ramp(double t) {
  static constexpr std::array<Rgb, 6> k{0x440154, 0x414487, 0x2A788E, 0x22A884, 0x7AD151, 0xFDE725};
  t = std::clamp(std::isfinite(t) ? t : 0.0, 0.0, 1.0) * (k.size() - 1);
  const auto i = std::min<std::size_t>(static_cast<std::size_t>(t), k.size() - 2);
  const double f = t - static_cast<double>(i);
  const auto mix = [&](int shift) {
    const double a = (k[i] >> shift) & 0xFF, b = (k[i + 1] >> shift) & 0xFF;
    return static_cast<Rgb>(std::lround(a + (b - a) * f)) << shift;
  };
  return mix(16) | mix(8) | mix(0);
}

std::string fmt(double v, int decimals) {
  char b[32];
  std::snprintf(b, sizeof b, "%.*f", decimals, v);
  return b;
}

struct Box {
  int x0, y0, x1, y1;  // the plot area, px
};

/// Min and max of the finite values (0, 1 when there are none); a flat field gets a unit span.
std::pair<double, double> span(const std::vector<double>& v) {
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (const double x : v)
    if (std::isfinite(x)) lo = std::min(lo, x), hi = std::max(hi, x);
  if (!(lo <= hi)) return {0.0, 1.0};
  if (hi - lo < 1e-12) return {lo - 0.5, hi + 0.5};
  return {lo, hi};
}

void colour_bar(Canvas& c, const Box& b, double lo, double hi, int decimals) {
  const int x0 = b.x1 + 14, x1 = x0 + 14;
  for (int y = b.y0; y < b.y1; ++y) c.rect(x0, y, x1, y + 1, ramp(1.0 - double(y - b.y0) / (b.y1 - b.y0 - 1)));
  c.text(x1 + 4, b.y0 - 4, fmt(hi, decimals), kInk);
  c.text(x1 + 4, b.y1 - 10, fmt(lo, decimals), kInk);
}

/// One heatmap: e up, µ right, a cell per grid point, the grip boundary in white.
void heatmap(Canvas& c, const Box& b, const std::string& title, const std::vector<SweepPoint>& pts,
             const SweepOptions& o, const std::function<double(const SweepPoint&)>& value, int decimals) {
  c.text(b.x0, b.y0 - 22, title, kInk, 1);
  const int ne = o.e.count, nm = o.mu.count;
  std::vector<double> v;
  for (const auto& p : pts) v.push_back(value(p));
  const auto [lo, hi] = span(v);
  const double cw = double(b.x1 - b.x0) / nm, ch = double(b.y1 - b.y0) / ne;
  for (int ie = 0; ie < ne; ++ie)
    for (int im = 0; im < nm; ++im) {
      const double x = v[static_cast<std::size_t>(ie * nm + im)];
      const int x0 = b.x0 + static_cast<int>(std::lround(im * cw)), x1 = b.x0 + static_cast<int>(std::lround((im + 1) * cw));
      const int y1 = b.y1 - static_cast<int>(std::lround(ie * ch)), y0 = b.y1 - static_cast<int>(std::lround((ie + 1) * ch));
      c.rect(x0, y0, x1, y1, std::isfinite(x) ? ramp((x - lo) / (hi - lo)) : 0x999999);
    }
  // The grip boundary through the cell centres: µ_grip of each e row, where it lies inside
  // the µ range (beyond it the whole row slips, or grips).
  double g_lo = std::numeric_limits<double>::infinity(), g_hi = -g_lo;
  for (int ie = 0; ie < ne; ++ie) {
    const double g = pts[static_cast<std::size_t>(ie * nm)].shot.impact.mu_grip;
    g_lo = std::min(g_lo, g), g_hi = std::max(g_hi, g);
  }
  if (g_lo >= 0.0 && (g_lo > o.mu.to || g_hi < o.mu.from))
    c.text(b.x0 + Canvas::text_width(title) + 12, b.y0 - 22,
           "(mu_grip " + fmt(g_lo, 2) + "-" + fmt(g_hi, 2) + (g_lo > o.mu.to ? ": all slip here)" : ": all grip here)"),
           0x666666);
  if (nm > 1 && o.mu.to > o.mu.from) {
    const auto x_of = [&](double mu) { return b.x0 + ((mu - o.mu.from) / (o.mu.to - o.mu.from) * (nm - 1) + 0.5) * cw; };
    const auto y_of = [&](int ie) { return b.y1 - (ie + 0.5) * ch; };
    bool have_prev = false;
    double px = 0, py = 0;
    for (int ie = 0; ie < ne; ++ie) {
      const double g = pts[static_cast<std::size_t>(ie * nm)].shot.impact.mu_grip;
      const bool inside = g >= o.mu.from && g <= o.mu.to;
      if (!inside) {
        have_prev = false;
        continue;
      }
      const double x = x_of(g), y = y_of(ie);
      if (have_prev) c.line(px, py, x, y, 0xFFFFFF, 1.5);
      c.disc(x, y, 3.5, 0xFFFFFF);
      have_prev = true;
      px = x;
      py = y;
    }
  }
  colour_bar(c, b, lo, hi, decimals);
  // Axes: µ along the bottom, e up the side.
  const std::string mu_lo = fmt(o.mu.from, 2), mu_hi = fmt(o.mu.to, 2);
  c.text(b.x0, b.y1 + 6, mu_lo, kInk);
  c.text(b.x1 - Canvas::text_width(mu_hi), b.y1 + 6, mu_hi, kInk);
  c.text((b.x0 + b.x1) / 2 - 40, b.y1 + 6, "friction mu", kInk);
  c.text(b.x0 - 8 - Canvas::text_width(fmt(o.e.from, 3)), b.y1 - 12, fmt(o.e.from, 3), kInk);
  c.text(b.x0 - 8 - Canvas::text_width(fmt(o.e.to, 3)), b.y0, fmt(o.e.to, 3), kInk);
  c.text(b.x0 - 30, (b.y0 + b.y1) / 2 - 6, "e", kInk, 2);
}

/// Landing points of the grid, side against carry, coloured by e (same ramp).
void dispersion(Canvas& c, const Box& b, const std::vector<SweepPoint>& pts, const SweepOptions& o, const DisplayUnits& u) {
  c.text(b.x0, b.y0 - 22, std::string("Dispersion: carry vs side at landing (") + u.distance_unit() + "), colour = e", kInk);
  std::vector<double> xs, ys;
  for (const auto& p : pts) {
    xs.push_back(u.dist(p.shot.trajectory.summary.lateral_m));
    ys.push_back(u.dist(p.shot.trajectory.summary.carry_m));
  }
  auto [x_lo, x_hi] = span(xs);
  auto [y_lo, y_hi] = span(ys);
  // Square-ish scale: side spread is small next to carry; keep a symmetric side axis.
  const double side = 1.15 * std::max({std::fabs(x_lo), std::fabs(x_hi), 0.05 * (y_hi - y_lo), 1.0});
  x_lo = -side, x_hi = side;
  const double pad = 0.05 * (y_hi - y_lo);
  y_lo -= pad, y_hi += pad;
  c.rect(b.x0, b.y0, b.x1, b.y1, 0xF4F4F4);
  const double cx = b.x0 + (0.0 - x_lo) / (x_hi - x_lo) * (b.x1 - b.x0);
  c.line(cx, b.y0, cx, b.y1, kGrid, 0.5);
  for (std::size_t k = 0; k < pts.size(); ++k) {
    const double x = b.x0 + (xs[k] - x_lo) / (x_hi - x_lo) * (b.x1 - b.x0);
    const double y = b.y1 - (ys[k] - y_lo) / (y_hi - y_lo) * (b.y1 - b.y0);
    const double t = o.e.to > o.e.from ? (pts[k].e - o.e.from) / (o.e.to - o.e.from) : 0.5;
    c.marker(x, y, 4.5, 3.5, ramp(t), kInk);
  }
  c.text(b.x0, b.y1 + 6, fmt(x_lo, 1) + " (left)", kInk);
  const std::string r = fmt(x_hi, 1) + " (right)";
  c.text(b.x1 - Canvas::text_width(r), b.y1 + 6, r, kInk);
  c.text(b.x0 - 8 - Canvas::text_width(fmt(y_lo, 0)), b.y1 - 12, fmt(y_lo, 0), kInk);
  c.text(b.x0 - 8 - Canvas::text_width(fmt(y_hi, 0)), b.y0, fmt(y_hi, 0), kInk);
}

}  // namespace

void write_sweep_plot(const std::vector<SweepPoint>& points, const SweepOptions& o, const DisplayUnits& u,
                      const std::string& title, const std::filesystem::path& png) {
  Canvas c(kWidth, kHeight, 0xFFFFFF);
  c.text(20, 14, "sweep " + title + ": " + std::to_string(o.e.count) + " e x " + std::to_string(o.mu.count) +
                     " mu; white line and dots: mu_grip(e), right of it the launch no longer changes with mu",
         kInk);
  const Box boxes[4] = {{80, 80, 500, 440}, {680, 80, 1100, 440}, {80, 530, 500, 890}, {680, 530, 1100, 890}};
  heatmap(c, boxes[0], std::string("Ball speed (") + u.speed_unit() + ")", points, o,
          [&](const SweepPoint& p) { return u.speed(p.shot.launch.ball_speed); }, 1);
  heatmap(c, boxes[1], "Total spin (rpm)", points, o,
          [](const SweepPoint& p) { return radps_to_rpm(p.shot.launch.spin.total); }, 0);
  if (o.fly) {
    heatmap(c, boxes[2], std::string("Carry (") + u.distance_unit() + ")", points, o,
            [&](const SweepPoint& p) { return u.dist(p.shot.trajectory.summary.carry_m); }, 1);
    dispersion(c, boxes[3], points, o, u);
  } else {
    c.text(boxes[2].x0, boxes[2].y0, "Carry: not computed (--no-flight)", kInk);
    c.text(boxes[3].x0, boxes[3].y0, "Dispersion: not computed (--no-flight)", kInk);
  }
  c.write_png(png);
}

}  // namespace sweetspot
