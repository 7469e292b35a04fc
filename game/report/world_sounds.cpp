#include "game/report/world_sounds.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>

#include "physics/math.hpp"

namespace sweetspot {
namespace {

// The ball (Rules of Golf, Equipment Appendix: 45.93 g at most) and the cup (Rules of Golf,
// Definitions, "Hole": 4.25 in across, at least 4 in deep).
constexpr double kBallMass = 0.04593;             // kg
constexpr double kCupDepth = 4.0 * 0.0254;        // m
// The ball on a plastic liner backed by soil keeps about half its speed at each bounce
// (ESTIMATE: a golf ball on hard plastic ~0.6-0.7, soil behind it absorbs more).
constexpr double kCupRestitution = 0.5;
// Contact time on the liner: a golf ball on a rigid face lasts ~0.45 ms at 45 m/s (Roberts,
// Jones & Rothberg 2001); Hertz's τ ∝ v^(−1/5) makes it ~0.9 ms at 1.4 m/s, and the plastic,
// far softer than steel, lengthens it (ESTIMATE: ×1.3).
double contact_time(double speed) { return 1.3 * 0.45e-3 * std::pow(std::max(speed, 0.05) / 45.0, -0.2); }

// A seeded white noise source in [−1, 1] (xorshift64*): the same loop every run.
struct Noise {
  std::uint64_t s;
  double next() {
    s ^= s >> 12;
    s ^= s << 25;
    s ^= s >> 27;
    return static_cast<double>((s * 0x2545F4914F6CDD1DULL) >> 11) / 4503599627370496.0 - 1.0;
  }
};

// One-pole low-pass coefficient for a cut-off `hz`.
double low_pass(double hz, int rate) { return 1.0 - std::exp(-2.0 * kPi * hz / rate); }

}  // namespace

const Ring& cup_ring() {
  // A thin plastic cylinder's ovalling modes: f_n = (h / 2πR²)·sqrt(E / 12ρ(1−ν²))·
  // n(n²−1)/sqrt(n²+1) (Rayleigh's inextensional modes). An ABS liner (E 2.3 GPa, ρ 1050
  // kg/m³, ν 0.35), 3 mm wall, 54 mm radius: n = 3, 4, 5 at ~570, ~1090 and ~1760 Hz. Set in
  // soil they die within tens of ms (decays and gains ESTIMATES; the liner's ring is most of
  // the rattle one hears).
  static const Ring r = [] {
    const double h = 0.003, R = 0.054, E = 2.3e9, rho = 1050.0, nu = 0.35;
    const double base = h / (2.0 * kPi * R * R) * std::sqrt(E / (12.0 * rho * (1.0 - nu * nu)));
    Ring x{"plastic cup liner", {}};
    for (int n = 3; n <= 5; ++n)
      x.modes.push_back({base * n * (n * n - 1) / std::sqrt(n * n + 1.0), 0.035 - 0.005 * (n - 3), 60.0});
    return x;
  }();
  return r;
}

std::vector<CupStrike> cup_strikes(double entry_speed) {
  std::vector<CupStrike> out;
  const auto strike = [&](double at, double speed) {
    CupStrike s;
    s.at = at;
    s.impact.contact_time = contact_time(speed);
    s.impact.normal_impulse = kBallMass * (1.0 + kCupRestitution) * speed;
    s.impact.ring = cup_ring();
    out.push_back(s);
  };
  // Across the 108 mm cup to its far wall, if it comes in rolling.
  double t = 0.0;
  if (entry_speed >= 0.05) {
    t = 0.108 / entry_speed;
    strike(std::min(t, 0.3), entry_speed);
  }
  // The fall to the bottom, then bounces: each up and down takes 2v/g, each e times the last.
  double v = std::sqrt(2.0 * kGravity * kCupDepth);
  double at = std::min(t, 0.3) + std::sqrt(2.0 * kCupDepth / kGravity);
  while (v > 0.05 && out.size() < 12) {
    strike(at, v);
    v *= kCupRestitution;
    at += 2.0 * v / kGravity;
  }
  return out;
}

double cup_entry_speed(const ShotTrajectory& holed) {
  for (auto it = holed.samples.rbegin(); it != holed.samples.rend(); ++it) {
    const double v = std::hypot(it->velocity.x(), it->velocity.z());
    if (v > 1e-6) return v;
  }
  return 0.0;
}

std::vector<float> synthesize_cup_drop(double entry_speed, int rate) {
  const std::vector<CupStrike> strikes = cup_strikes(entry_speed);
  const double tail = 0.3;  // s after the last strike: the last ring dies away
  const double seconds = (strikes.empty() ? 0.0 : strikes.back().at) + tail;
  std::vector<float> out(static_cast<std::size_t>(seconds * rate), 0.0f);
  for (const CupStrike& s : strikes) {
    const std::vector<float> one = synthesize_impact(s.impact, rate, tail);
    const auto from = static_cast<std::size_t>(s.at * rate);
    for (std::size_t i = 0; i < one.size() && from + i < out.size(); ++i)
      out[from + i] = static_cast<float>(std::tanh(static_cast<double>(out[from + i]) + one[i]));
  }
  return out;
}

std::vector<float> synthesize_ambience(Ambience kind, double wind_speed, int rate, double seconds) {
  if (kind == Ambience::None || rate <= 0 || !(seconds > 0.0)) return {};
  const std::size_t n = static_cast<std::size_t>(seconds * rate);
  std::vector<double> p(n, 0.0);
  Noise noise{kind == Ambience::Course ? 0x9E3779B97F4A7C15ULL : 0xD1B54A32D192ED03ULL};
  if (kind == Ambience::Course) {
    // Wind in the open: noise below ~300 Hz whose level grows with the wind (ESTIMATE: the
    // square of the speed, from a whisper at 2 m/s to a roar near 15 m/s), swelling in gusts.
    const double level = 0.02 + 0.25 * std::min(1.0, std::pow(std::max(wind_speed, 0.0) / 15.0, 2.0));
    const double k = low_pass(300.0, rate);
    double lp = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
      lp += k * (noise.next() - lp);
      const double t = static_cast<double>(i) / rate;
      const double gust = 1.0 + 0.35 * std::sin(2.0 * kPi * t / seconds) * std::sin(2.0 * kPi * 3.0 * t / seconds);
      p[i] += level * gust * lp * 3.0;
    }
    // A bird now and then: a few rising chirps near 3-4 kHz (ESTIMATE of a songbird's call).
    for (double start = 0.7; start + 0.5 < seconds; start += 2.9) {
      for (int c = 0; c < 3; ++c) {
        const double t0 = start + 0.12 * c, dur = 0.07, f0 = 3000.0 + 250.0 * c;
        const auto i0 = static_cast<std::size_t>(t0 * rate);
        double phase = 0.0;
        for (std::size_t i = i0; i < std::min(n, i0 + static_cast<std::size_t>(dur * rate)); ++i) {
          const double u = static_cast<double>(i - i0) / (dur * rate);
          phase += 2.0 * kPi * (f0 + 900.0 * u) / rate;
          p[i] += 0.04 * std::sin(kPi * u) * std::sin(phase);
        }
      }
    }
  } else {
    // A crowd's murmur: many voices, noise in the speech band (~200-2000 Hz), its level
    // drifting slowly as conversations come and go (ESTIMATE).
    const double hi = low_pass(2000.0, rate), lo = low_pass(200.0, rate);
    double a = 0.0, b = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
      const double x = noise.next();
      a += hi * (x - a);
      b += lo * (a - b);
      const double t = static_cast<double>(i) / rate;
      const double swell = 1.0 + 0.25 * std::sin(2.0 * kPi * 2.0 * t / seconds);
      p[i] += 0.12 * swell * (a - b) * 2.5;
    }
  }
  // The loop's seam: the last half second fades into the first, so it repeats without a click.
  const std::size_t fade = std::min(n / 2, static_cast<std::size_t>(0.5 * rate));
  std::vector<float> out(n - fade);
  for (std::size_t i = 0; i < out.size(); ++i) {
    double x = p[i];
    if (i < fade) {
      const double w = static_cast<double>(i) / fade;
      x = w * p[i] + (1.0 - w) * p[n - fade + i];
    }
    out[i] = static_cast<float>(std::tanh(x));
  }
  return out;
}

}  // namespace sweetspot
