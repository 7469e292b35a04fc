#include "support/random_world.hpp"

#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>

#include "physics/launch.hpp"
#include "physics/units.hpp"

namespace sweetspot::test {

namespace {

constexpr double kPi = 3.14159265358979;

HeightField random_field(soak::Rng& g) {
  HeightField f;
  f.nx = 40;
  f.nz = 16;
  f.h = g.in(4.0, 10.0);
  f.x0 = -2.0 * f.h;
  f.z0 = -0.5 * f.nz * f.h;
  f.y.assign(static_cast<std::size_t>((f.nx + 1) * (f.nz + 1)), 0.0);
  // Gentle rolls, a few creases (V ditches) across or along the line of play, steps, bumps.
  const double roll = g.in(0.0, 3.0), wavelength = g.in(30.0, 150.0);
  struct Crease { double x, z, dx, dz, depth, half_width; };
  std::vector<Crease> creases;
  for (int n = g.below(4); n > 0; --n) {
    const double angle = g.in(0.0, kPi);
    creases.push_back({g.in(0.0, f.nx * f.h), g.in(f.z0, -f.z0), std::cos(angle), std::sin(angle), g.in(0.2, 8.0),
                       g.in(0.5, 3.0) * f.h});
  }
  const double step_at = g.uniform() < 0.3 ? g.in(10.0, f.nx * f.h) : 1e9, step = g.in(-3.0, 3.0);
  for (int k = 0; k <= f.nz; ++k)
    for (int i = 0; i <= f.nx; ++i) {
      const double x = f.x0 + i * f.h, z = f.z0 + k * f.h;
      double y = roll * std::sin(2.0 * kPi * x / wavelength) * std::cos(z / wavelength);
      for (const Crease& c : creases) {
        const double across = std::abs(-(x - c.x) * c.dz + (z - c.z) * c.dx);  // distance from the crease line
        if (across < c.half_width) y -= c.depth * (1.0 - across / c.half_width);
      }
      if (x > step_at) y += step;
      y += g.in(-0.05, 0.05) * f.h;  // bumps
      if (i <= 2 && std::abs(z) <= 2.0 * f.h) y = 0.0;  // a flat tee at the origin
      f.y[static_cast<std::size_t>(k * (f.nx + 1) + i)] = y;
    }
  return f;
}

WorldDescription describe(const HeightField& f, soak::Rng& g) {
  WorldDescription d;
  d.name = "soak";
  d.materials = assets().materials();
  const auto index = [&](const char* name) {
    for (std::size_t m = 0; m < d.materials.size(); ++m)
      if (d.materials[m].name == name) return static_cast<int>(m);
    throw std::runtime_error(std::string("random_world: the shipped materials have no ") + name);
  };
  const int kinds[] = {index("fairway"), index("rough"), index("sand"), index("green"), index("water")};
  std::vector<WorldMesh> meshes(5);
  for (int m = 0; m < 5; ++m) meshes[static_cast<std::size_t>(m)].material = kinds[m];
  for (int k = 0; k < f.nz; ++k)
    for (int i = 0; i < f.nx; ++i) {
      const int r = g.below(100);
      const int m = i <= 2 ? 0 : r < 55 ? 0 : r < 75 ? 1 : r < 85 ? 2 : r < 96 ? 3 : 4;
      WorldMesh& wm = meshes[static_cast<std::size_t>(m)];
      const auto v = [&](int a, int b) {
        wm.vertices.emplace_back(f.x0 + a * f.h, f.at(a, b), f.z0 + b * f.h);
        return static_cast<std::uint32_t>(wm.vertices.size() - 1);
      };
      const std::uint32_t a = v(i, k), b = v(i + 1, k), c = v(i + 1, k + 1), e = v(i, k + 1);
      // Counter-clockwise seen from above (+y): a, c, b and a, e, c.
      wm.indices.insert(wm.indices.end(), {a, c, b, a, e, c});
    }
  for (auto& m : meshes)
    if (!m.indices.empty()) d.meshes.push_back(std::move(m));
  d.bounds_min = Vec3(f.x0, -60.0, f.z0);
  d.bounds_max = Vec3(f.x0 + f.nx * f.h, 400.0, -f.z0);
  return d;
}

}  // namespace

bool HeightField::height(double x, double z, double* out) const {
  const double u = (x - x0) / h, w = (z - z0) / h;
  const int i = static_cast<int>(std::floor(u)), k = static_cast<int>(std::floor(w));
  if (i < 0 || k < 0 || i >= nx || k >= nz) return false;
  const double fu = u - i, fw = w - k;
  const double a = at(i, k), b = at(i + 1, k), c = at(i + 1, k + 1), d = at(i, k + 1);
  *out = fu >= fw ? a + fu * (b - a) + fw * (c - b) : a + fw * (d - a) + fu * (c - d);
  return true;
}

RandomWorld::RandomWorld(std::uint64_t seed, long index)
    : rng(seed * 0x9E3779B97F4A7C15ULL + static_cast<std::uint64_t>(index)),
      field(random_field(rng)),
      description(describe(field, rng)) {}

FlightCase random_golf_shot(soak::Rng& g, char* text, std::size_t text_size) {
  const double mph = g.uniform() < 0.3 ? g.in(1.0, 15.0) : g.in(15.0, 175.0);
  const double launch = mph < 15.0 ? g.in(-2.0, 5.0) : g.in(-5.0, 50.0);
  const double hla = g.in(-20.0, 20.0), rpm = g.in(0.0, 10000.0), axis = g.in(-40.0, 40.0);
  FlightCase c = golf_launch(mph, launch, rpm);
  c.launch = launch_from_metrics(mph_to_mps(mph), deg_to_rad(launch), deg_to_rad(hla), rpm_to_radps(rpm),
                                 deg_to_rad(axis), Vec3(0.0, c.ball.radius, 0.0));
  if (text != nullptr)
    std::snprintf(text, text_size, "%.2f mph, %.2f deg, hla %.2f deg, %.0f rpm, axis %.2f deg", mph, launch, hla, rpm,
                  axis);
  return c;
}

}  // namespace sweetspot::test
