// The strike's sound (game/report/impact_sound.hpp): contact times from the impact with
// duration, the pulse's spectrum, each body's ring, loudness, and the WAV it writes.
#include <catch2/catch.hpp>

#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <cstdint>
#include <string>
#include <vector>

#include "game/content/scenario.hpp"
#include "game/report/impact_sound.hpp"
#include "game/rules/run_shot.hpp"
#include "physics/math.hpp"
#include "support/test_assets.hpp"

namespace sweetspot {
namespace {

ShotResult strike(const std::string& scenario, const std::vector<std::string>& sets = {}) {
  return run_scenario(load_scenario(test::assets(), scenario, sets), RunOptions{false, false});
}

ShotSound sound_of(const std::string& scenario, const std::vector<std::string>& sets = {}) {
  const ShotSound s = impact_sound_of(strike(scenario, sets));
  REQUIRE(s.ok);
  return s;
}

// Amplitude of the samples' component at `hz` (Goertzel), per sample.
double level_at(const std::vector<float>& x, double hz, int rate = 48000) {
  const double w = 2.0 * kPi * hz / rate, c = 2.0 * std::cos(w);
  double s1 = 0.0, s2 = 0.0;
  for (float v : x) {
    const double s0 = v + c * s1 - s2;
    s2 = s1;
    s1 = s0;
  }
  return std::sqrt(std::max(0.0, s1 * s1 + s2 * s2 - c * s1 * s2)) / static_cast<double>(x.size());
}

double peak(const std::vector<float>& x) {
  double p = 0.0;
  for (float v : x) p = std::max(p, static_cast<double>(std::abs(v)));
  return p;
}

// Power-weighted mean frequency over 100 Hz .. 12 kHz in 100 Hz steps.
double centroid(const std::vector<float>& x) {
  double num = 0.0, den = 0.0;
  for (double f = 100.0; f <= 12000.0; f += 100.0) {
    const double a = level_at(x, f);
    num += f * a * a;
    den += a * a;
  }
  return num / den;
}

const std::vector<std::string> kPutt{"club.name=putter", "swing.speed=2.5m/s", "swing.attack_angle=2deg"};
const std::vector<std::string> kAlloy{"bat.name=bbcor"};

}  // namespace

TEST_CASE("contact times come from the impact with duration, as measured", "[impact_sound]") {
  const double driver = strike("golf/driver").impact.contact_time;
  const double iron = strike("golf/7-iron").impact.contact_time;
  const double putt = strike("golf/7-iron", kPutt).impact.contact_time;
  const double bat = strike("baseball/line-drive").impact.contact_time;
  // A golf ball stays on a driver's face ~0.45 ms (S. R. Roberts, R. Jones & S. J. Rothberg,
  // "Measurement of contact time in short duration sports ball impacts", Sports Eng. 4 (2001)
  // 191); a baseball on a bat ~0.7 ms (A. M. Nathan, Am. J. Phys. 68 (2000) 979).
  CHECK(driver == Approx(0.45e-3).margin(0.08e-3));
  CHECK(bat == Approx(0.7e-3).margin(0.15e-3));
  // Hertz: τ ∝ v^(−1/5), so a slower strike stays on longer: the iron's slower face a little,
  // a 2.5 m/s putt almost twice as long as the drive.
  CHECK(iron > driver);
  CHECK(putt > 1.5 * driver);
}

TEST_CASE("the force pulse's spectrum: one at zero, its first zero at 1.5/τ", "[impact_sound]") {
  const double tau = 0.5e-3;
  CHECK(pulse_spectrum_ratio(0.0, tau) == Approx(1.0));
  CHECK(pulse_spectrum_ratio(1.5 / tau, tau) == Approx(0.0).margin(1e-9));
  // Continuous through f = 1/(2τ), where cos and the denominator vanish together.
  CHECK(pulse_spectrum_ratio(1.0 / (2.0 * tau), tau) == Approx(kPi / 4.0));
  CHECK(pulse_spectrum_ratio(1.0 / (2.0 * tau) + 1e-3, tau) == Approx(kPi / 4.0).epsilon(1e-4));
  // Within the main lobe a longer contact passes less of a mode's frequency.
  CHECK(pulse_spectrum_ratio(2000.0, 0.4e-3) > pulse_spectrum_ratio(2000.0, 0.7e-3));
}

TEST_CASE("each club and bat sounds as its contact and ring say", "[impact_sound]") {
  const ShotSound driver = sound_of("golf/driver"), iron = sound_of("golf/7-iron"), putt = sound_of("golf/7-iron", kPutt);
  const ShotSound wood = sound_of("baseball/line-drive"), alloy = sound_of("baseball/line-drive", kAlloy);
  CHECK(driver.input.ring.kind == "hollow titanium driver");
  CHECK(iron.input.ring.kind == "solid steel iron");
  CHECK(putt.input.ring.kind == "solid steel putter");
  CHECK(wood.input.ring.kind == "solid wood bat");
  CHECK(alloy.input.ring.kind == "hollow alloy bat");
  const auto d = synthesize_impact(driver.input), i = synthesize_impact(iron.input), p = synthesize_impact(putt.input);
  const auto w = synthesize_impact(wood.input), a = synthesize_impact(alloy.input);
  // The alloy bat's ping: its hoop mode at 1.8 kHz, which a solid wood bat has not.
  CHECK(level_at(a, 1800.0) > 20.0 * level_at(w, 1800.0));
  // Their bending modes are the same beam's: equal at the first.
  CHECK(level_at(a, 170.0) == Approx(level_at(w, 170.0)).epsilon(0.05));
  // The driver rings in its 3-5 kHz band; the solid iron there only clicks.
  CHECK(level_at(d, 4000.0) > 10.0 * level_at(i, 4000.0));
  // The bats' low bending modes pull their sound far below the clubs'.
  CHECK(centroid(w) < 0.5 * centroid(d));
  // A putt's long, soft contact: far quieter than a drive, and duller than the iron's click.
  CHECK(peak(p) < 0.1 * peak(d));
  CHECK(centroid(p) < centroid(i));
}

TEST_CASE("the same ring struck longer sounds duller; struck harder, louder", "[impact_sound]") {
  ImpactSoundInput in;
  in.ring = ring_for("driver", "golf");
  in.normal_impulse = 3.3;
  in.contact_time = 0.40e-3;
  const auto short_hit = synthesize_impact(in);
  in.contact_time = 0.60e-3;
  const auto long_hit = synthesize_impact(in);
  CHECK(centroid(long_hit) < centroid(short_hit));
  in.contact_time = 0.45e-3;
  in.normal_impulse = 1.0;
  const auto soft = synthesize_impact(in);
  in.normal_impulse = 3.0;
  const auto hard = synthesize_impact(in);
  CHECK(peak(hard) > 2.0 * peak(soft));
  CHECK(peak(hard) <= 1.0);
  // Deterministic, sample for sample.
  CHECK(synthesize_impact(in) == hard);
}

TEST_CASE("no strike, no sound", "[impact_sound]") {
  ImpactSoundInput in;
  in.ring = ring_for("driver", "golf");
  const auto quiet = synthesize_impact(in, 48000, 0.1);
  CHECK(quiet.size() == 4800);
  CHECK(peak(quiet) == 0.0);
  // Unknown equipment rings as the sport's commonest body.
  CHECK(ring_for("my-custom-6-iron", "golf").kind == "solid steel iron");
  CHECK(ring_for("ash", "baseball").kind == "solid wood bat");
}

TEST_CASE("a fairway wood rings between the driver and the irons", "[impact_sound]") {
  const ShotSound wood = sound_of("golf/3-wood"), driver = sound_of("golf/driver");
  CHECK(wood.input.ring.kind == "hollow steel fairway wood");
  // Its smaller head stays on the ball about as long as the driver's...
  CHECK(wood.input.contact_time == Approx(driver.input.contact_time).epsilon(0.15));
  // ...and rings higher: its 6.1 kHz mode is there, the driver's 3.2-5 kHz ones are not.
  const auto w = synthesize_impact(wood.input), d = synthesize_impact(driver.input);
  CHECK(level_at(w, 6100.0) > 10.0 * level_at(d, 6100.0));
  CHECK(level_at(d, 4000.0) > 10.0 * level_at(w, 4000.0));
}

TEST_CASE("shot --sound's file holds the strike's synthesised samples", "[impact_sound]") {
  const ShotResult shot = strike("baseball/line-drive", kAlloy);
  const auto path = std::filesystem::temp_directory_path() / ("sweetspot_test_sound_" + std::to_string(::getpid()) + ".wav");
  write_impact_wav(shot, path, "--sound");
  std::ifstream f(path, std::ios::binary);
  const std::string bytes((std::istreambuf_iterator<char>(f)), std::istreambuf_iterator<char>());
  std::filesystem::remove(path);
  const std::vector<float> x = synthesize_impact(impact_sound_of(shot).input);
  REQUIRE(bytes.size() == 44 + 2 * x.size());
  CHECK(bytes == wav_bytes(x, kImpactSampleRate));
  // A shot without a strike is refused, naming the flag, and nothing is written.
  ShotResult launch_only = shot;
  launch_only.impact.present = false;
  CHECK_THROWS_WITH(write_impact_wav(launch_only, path, "--sound"), Catch::Contains("--sound"));
  CHECK_FALSE(std::filesystem::exists(path));
}

TEST_CASE("the WAV holds the synthesised samples as 16-bit PCM", "[impact_sound]") {
  const std::vector<float> x{0.0f, 0.5f, -0.5f, 1.0f, -1.0f, 2.0f};
  const std::string b = wav_bytes(x, 48000);
  REQUIRE(b.size() == 44 + 2 * x.size());
  const auto u32 = [&](std::size_t at) {
    std::uint32_t v = 0;
    for (int k = 3; k >= 0; --k) v = (v << 8) | static_cast<unsigned char>(b[at + static_cast<std::size_t>(k)]);
    return v;
  };
  const auto i16 = [&](std::size_t at) {
    return static_cast<std::int16_t>(static_cast<unsigned char>(b[at]) | (static_cast<unsigned char>(b[at + 1]) << 8));
  };
  CHECK(b.substr(0, 4) == "RIFF");
  CHECK(u32(4) == b.size() - 8);
  CHECK(b.substr(8, 8) == "WAVEfmt ");
  CHECK(u32(24) == 48000);
  CHECK(b.substr(36, 4) == "data");
  CHECK(u32(40) == 2 * x.size());
  CHECK(i16(44) == 0);
  CHECK(i16(46) == 16384);
  CHECK(i16(48) == -16384);
  CHECK(i16(50) == 32767);
  CHECK(i16(52) == -32767);
  CHECK(i16(54) == 32767);  // clipped, never wrapped
}

}  // namespace sweetspot
