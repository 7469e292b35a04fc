#include "game/report/impact_sound.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "game/core/shot_result.hpp"
#include "game/util/atomic_file.hpp"
#include "physics/error.hpp"
#include "physics/math.hpp"

namespace sweetspot {
namespace {

// A free-free beam's bending modes stand at (βL)² = 22.37, 61.67, 120.9, 199.9 (Euler-
// Bernoulli: βL = 4.730, 7.853, 10.996, 14.137), i.e. 1 : 2.757 : 5.404 : 8.933. A held bat
// vibrates as a free one (D. A. Russell, "Vibrational modes of a baseball bat", Kettering
// University, 2003: the grip barely moves the frequencies).
constexpr double kBeamRatio2 = 2.757, kBeamRatio3 = 5.404, kBeamRatio4 = 8.933;
// A wood bat's first bending mode: ~170 Hz (Russell 2003).
constexpr double kBatFirstBending = 170.0;  // Hz

// First bending mode of a solid rectangular steel blade as a free-free beam:
// f = 22.37/(2π L²)·t·sqrt(E/(12ρ)), E 200 GPa, ρ 7850 kg/m³.
double steel_blade_hz(double length, double thickness) {
  return 22.37 / (2.0 * kPi * length * length) * thickness * std::sqrt(200e9 / (12.0 * 7850.0));
}

// The hands damp a bat's bending modes within a few tens of ms (Russell 2003); the decays and
// the gains of the bending modes are ESTIMATES: a 66 mm barrel radiates little at these
// frequencies (ka ≈ 0.1 at 170 Hz), so its "crack" is mostly the click.
std::vector<RingMode> bat_bending() {
  const double f = kBatFirstBending;
  return {{f, 0.020, 0.2}, {f * kBeamRatio2, 0.015, 0.4}, {f * kBeamRatio3, 0.010, 0.6}, {f * kBeamRatio4, 0.008, 0.8}};
}

const Ring& wood_bat() {
  static const Ring r{"solid wood bat", bat_bending()};
  return r;
}

const Ring& alloy_bat() {
  // The hollow barrel adds its hoop mode, the "ping": 1.0-2.5 kHz across alloy and composite
  // bats (D. A. Russell, "Acoustics and vibration of baseball and softball bats", Acoustics
  // Today 13(4), 2017), 1.8 kHz here. It lives in the barrel alone, so the hands do not damp
  // it: it rings long (decay 80 ms, ESTIMATE) and loud (gain 3, ESTIMATE: the ping is what
  // one hears of an alloy bat).
  static const Ring r = [] {
    Ring x{"hollow alloy bat", bat_bending()};
    x.modes.push_back({1800.0, 0.080, 3.0});
    return x;
  }();
  return r;
}

const Ring& driver() {
  // A 460 cc titanium head rings at 2.5-5 kHz, and makers tune it above 3 kHz, near 4 kHz,
  // damped quickly (Golf Australia, "The science of sound", 2013, quoting Mizuno's and
  // Callaway's R&D). Decays 15 ms and gains (the ring about as loud as the click) ESTIMATES.
  static const Ring r{"hollow titanium driver", {{3200.0, 0.015, 20.0}, {4000.0, 0.012, 12.0}, {5000.0, 0.010, 8.0}}};
  return r;
}

const Ring& fairway_wood() {
  // A smaller hollow steel head (~175 cc): plate modes scale as 1/size², (460/175)^(2/3) ≈ 1.9
  // times the driver's (ESTIMATE of the scaling; walls are thicker too).
  static const Ring r{"hollow steel fairway wood", {{6100.0, 0.012, 10.0}, {7600.0, 0.010, 6.0}}};
  return r;
}

const Ring& iron() {
  // A solid steel blade ~75 mm long, ~8 mm thick on average: ~7.4 kHz; its next mode (x2.76)
  // is past hearing's useful range. Decay 10 ms, gain 5: ESTIMATES.
  static const Ring r{"solid steel iron", {{steel_blade_hz(0.075, 0.008), 0.010, 5.0}}};
  return r;
}

const Ring& putter() {
  // A solid steel putter head ~100 mm long, ~15 mm thick: ~7.8 kHz. A slow stroke's long
  // contact barely excites it: a putt is a soft click. Decay 20 ms, gain 5: ESTIMATES.
  static const Ring r{"solid steel putter", {{steel_blade_hz(0.100, 0.015), 0.020, 5.0}}};
  return r;
}

// Full scale: the click's peak rate of force change near a 120 mph drive (a half-sine of
// 3.5 N·s over 0.45 ms peaks at 1.2e4 N and changes at up to 8.6e7 N/s); a bat's harder
// crack reaches ~1.3e8 N/s. 1.5e8 N/s keeps both below clipping before the soft limit.
constexpr double kFullScale = 1.5e8;  // N/s

}  // namespace

const Ring& ring_for(std::string_view name, std::string_view sport) {
  if (name == "driver") return driver();
  if (name == "3-wood" || name == "5-wood" || name == "hybrid") return fairway_wood();
  if (name == "putter") return putter();
  if (name == "bbcor") return alloy_bat();
  if (name == "maple") return wood_bat();
  return sport == "baseball" ? wood_bat() : iron();
}

double pulse_spectrum_ratio(double hz, double tau) {
  const double x = 2.0 * hz * tau;  // f over the frequency whose half-period is the contact
  const double den = 1.0 - x * x;
  if (std::abs(den) < 1e-9) return kPi / 4.0;  // the limit at f = 1/(2τ)
  return std::abs(std::cos(kPi * hz * tau)) / std::abs(den);
}

std::vector<float> synthesize_impact(const ImpactSoundInput& in, int rate, double seconds) {
  const std::size_t n = static_cast<std::size_t>(std::max(0.0, seconds) * rate);
  std::vector<float> out(n, 0.0f);
  const double tau = in.contact_time, J = in.normal_impulse;
  if (!(tau > 0.0) || !(J > 0.0) || rate <= 0) return out;
  // The contact's force, a half-sine of duration τ carrying the impulse J: F(t) = F̂ sin(πt/τ),
  // F̂ = πJ/(2τ). A small body accelerated by F radiates as a dipole whose far-field pressure
  // follows dF/dt ("acceleration noise": E. J. Richards, M. E. Westcott & R. K. Jeyapalan,
  // "On the prediction of impact noise", J. Sound Vib. 62 (1979) 547).
  const double peak_force = kPi * J / (2.0 * tau);
  const double click = peak_force * kPi / tau / kFullScale;  // peak of dF/dt, full scale 1
  const double dt = 1.0 / rate;
  std::vector<double> p(n, 0.0);
  for (std::size_t i = 0; i < n; ++i) {
    const double t = (static_cast<double>(i) + 0.5) * dt;
    if (t < tau) p[i] += click * std::cos(kPi * t / tau);
  }
  // Each mode rings from separation on, excited by the pulse's spectrum at its frequency.
  for (const RingMode& m : in.ring.modes) {
    if (m.hz <= 0.0 || m.decay <= 0.0 || m.hz >= 0.5 * rate) continue;
    const double a = m.gain * pulse_spectrum_ratio(m.hz, tau) * click;
    const double w = 2.0 * kPi * m.hz;
    for (std::size_t i = 0; i < n; ++i) {
      const double t = static_cast<double>(i) * dt - tau;
      if (t < 0.0) continue;
      p[i] += a * std::exp(-t / m.decay) * std::sin(w * t);
    }
  }
  // A soft limit instead of clipping: a harder hit is louder, never harsher than full scale.
  for (std::size_t i = 0; i < n; ++i) out[i] = static_cast<float>(std::tanh(p[i]));
  return out;
}

ShotSound impact_sound_of(const ShotResult& shot) {
  ShotSound s;
  if (!shot.impact.present || !(shot.impact.contact_time > 0.0)) return s;
  const std::string& name = !shot.club.club.empty() ? shot.club.club : shot.bat.bat;
  s.input.contact_time = shot.impact.contact_time;
  s.input.normal_impulse = shot.impact.normal_impulse;
  s.input.ring = ring_for(name, shot.sport);
  s.ok = true;
  return s;
}

std::string wav_bytes(const std::vector<float>& samples, int rate) {
  std::string b;
  const auto u32 = [&](std::uint32_t v) {
    for (int i = 0; i < 4; ++i) b.push_back(static_cast<char>((v >> (8 * i)) & 0xFF));
  };
  const auto u16 = [&](std::uint16_t v) {
    b.push_back(static_cast<char>(v & 0xFF));
    b.push_back(static_cast<char>(v >> 8));
  };
  const std::uint32_t data = static_cast<std::uint32_t>(samples.size() * 2);
  b += "RIFF";
  u32(36 + data);
  b += "WAVEfmt ";
  u32(16);                                      // PCM header size
  u16(1);                                       // PCM
  u16(1);                                       // mono
  u32(static_cast<std::uint32_t>(rate));
  u32(static_cast<std::uint32_t>(rate) * 2);    // bytes per second
  u16(2);                                       // bytes per frame
  u16(16);                                      // bits per sample
  b += "data";
  u32(data);
  for (float x : samples) {
    const double c = std::clamp(static_cast<double>(x), -1.0, 1.0);
    u16(static_cast<std::uint16_t>(static_cast<std::int16_t>(std::lround(c * 32767.0))));
  }
  return b;
}

void write_impact_wav(const ShotResult& shot, const std::filesystem::path& path, const char* flag) {
  const ShotSound sound = impact_sound_of(shot);
  if (!sound.ok)
    throw InputError(std::string(flag) + " " + path.string() +
                     ": this shot has no strike with a contact time to sound (a launch-only shot, or impact.model = "
                     "\"rigid\")");
  write_file_atomic(path, wav_bytes(synthesize_impact(sound.input), kImpactSampleRate));
}

}  // namespace sweetspot
