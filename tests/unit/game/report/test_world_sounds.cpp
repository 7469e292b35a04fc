// The world's sounds (game/report/world_sounds.hpp): the holed ball's strikes in the cup
// follow its fall and bounces (free fall, restitution), the liner rings at a thin
// cylinder's ovalling modes, and the ambience loops without a click and rises with the wind.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>

#include "game/report/world_sounds.hpp"
#include "physics/math.hpp"

using namespace sweetspot;

namespace {
double rms(const std::vector<float>& s) {
  double e = 0.0;
  for (float x : s) e += double(x) * x;
  return s.empty() ? 0.0 : std::sqrt(e / s.size());
}
}  // namespace

TEST_CASE("a holed ball strikes the far wall, falls 4 in and bounces lower each time", "[report][sound]") {
  const double entry = 1.0;  // m/s, rolling in
  const std::vector<CupStrike> s = cup_strikes(entry);
  REQUIRE(s.size() >= 4);
  // Across the 4.25 in cup to its far wall at the speed it came in.
  CHECK(s[0].at == Approx(0.108 / entry));
  CHECK(s[0].impact.normal_impulse == Approx(0.04593 * 1.5 * entry));
  // Then free fall through the cup's 4 in: sqrt(2h/g) later, at sqrt(2gh).
  const double h = 4.0 * 0.0254, g = kGravity;
  CHECK(s[1].at - s[0].at == Approx(std::sqrt(2.0 * h / g)).epsilon(1e-9));
  CHECK(s[1].impact.normal_impulse == Approx(0.04593 * 1.5 * std::sqrt(2.0 * g * h)).epsilon(1e-9));
  for (std::size_t i = 2; i < s.size(); ++i) {
    // Each bounce e = 0.5 times the last: the impulse halves, so does the time aloft.
    CHECK(s[i].impact.normal_impulse == Approx(0.5 * s[i - 1].impact.normal_impulse).epsilon(1e-9));
    if (i >= 3) CHECK((s[i].at - s[i - 1].at) == Approx(0.5 * (s[i - 1].at - s[i - 2].at)).epsilon(1e-9));
    // A softer strike lasts longer (Hertz: τ ∝ v^(-1/5)).
    CHECK(s[i].impact.contact_time > s[i - 1].impact.contact_time);
  }
  // Dropped straight in (a ball that barely reached the lip): no wall strike.
  CHECK(cup_strikes(0.0).front().at == Approx(std::sqrt(2.0 * h / g)));
}

TEST_CASE("the cup's liner rings at a thin plastic cylinder's ovalling modes", "[report][sound]") {
  const Ring& r = cup_ring();
  REQUIRE(r.modes.size() == 3);
  // Rayleigh's inextensional modes go as n(n²−1)/sqrt(n²+1): 7.589, 14.552, 23.534 for n = 3..5.
  CHECK(r.modes[1].hz / r.modes[0].hz == Approx(14.552 / 7.589).epsilon(1e-3));
  CHECK(r.modes[2].hz / r.modes[0].hz == Approx(23.534 / 7.589).epsilon(1e-3));
  // 3 mm ABS, 54 mm radius: the lowest audible one near 570 Hz.
  CHECK(r.modes[0].hz == Approx(567.0).epsilon(0.02));
  // The rattle: the first strike is the loudest, the sound dies with the bounces, nothing clips.
  const std::vector<float> drop = synthesize_cup_drop(1.0);
  REQUIRE(drop.size() > std::size_t(0.4 * kImpactSampleRate));
  const auto peak_near = [&](double at) {
    const auto i0 = std::size_t(at * kImpactSampleRate);
    float p = 0.0f;
    for (std::size_t i = i0; i < std::min(drop.size(), i0 + 480); ++i) p = std::max(p, std::abs(drop[i]));
    return p;
  };
  const std::vector<CupStrike> s = cup_strikes(1.0);
  CHECK(peak_near(s[1].at) > peak_near(s.back().at));
  CHECK(peak_near(s[1].at) > 0.0f);
  for (float x : drop) REQUIRE(std::abs(x) < 1.0f);
}

TEST_CASE("the ambience loops without a click, is the same every time and rises with the wind", "[report][sound]") {
  CHECK(synthesize_ambience(Ambience::None, 5.0).empty());
  for (Ambience kind : {Ambience::Course, Ambience::Ballpark}) {
    const std::vector<float> a = synthesize_ambience(kind, 5.0);
    REQUIRE(a.size() > std::size_t(5 * kImpactSampleRate));
    CHECK(a == synthesize_ambience(kind, 5.0));
    // The seam (last sample to first) is no bigger a step than the loop's own steps.
    float biggest = 0.0f;
    for (std::size_t i = 1; i < a.size(); ++i) biggest = std::max(biggest, std::abs(a[i] - a[i - 1]));
    CHECK(std::abs(a.front() - a.back()) <= biggest);
    CHECK(rms(a) > 0.005);
    for (float x : a) REQUIRE(std::abs(x) < 1.0f);
  }
  CHECK(rms(synthesize_ambience(Ambience::Course, 12.0)) > 2.0 * rms(synthesize_ambience(Ambience::Course, 2.0)));
}
