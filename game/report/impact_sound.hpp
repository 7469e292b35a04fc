// The sound of a strike, synthesised from the impact the physics solved (issue 44): the
// contact's force pulse, whose duration and peak come from the impact with duration, drives
// a click (the pressure a body radiates while it is accelerated) and the ring of the struck
// club or bat (its vibration modes, each excited by the pulse's spectrum at its frequency).
// A short, hard contact excites high modes; a long, soft one only the low ones: that is why
// a driver, an iron, a putter, a wood bat and an alloy bat sound different.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace sweetspot {

struct ShotResult;

/// One vibration mode of the struck body.
struct RingMode {
  double hz = 0.0;     ///< frequency
  double decay = 0.0;  ///< s for its amplitude to fall by e
  /// Its peak pressure against the click's when the contact is short enough to excite it
  /// fully (the pulse's spectrum at its frequency as high as at zero).
  double gain = 0.0;
};

/// How a club or bat rings when struck.
struct Ring {
  std::string kind;              ///< "hollow titanium driver", "solid steel iron", ...
  std::vector<RingMode> modes;
};

/// The ring of the equipment named `equipment` ("driver", "7-iron", "maple", "bbcor");
/// a name it does not know rings as its sport's commonest body (`sport` "golf": an iron;
/// "baseball": a wood bat).
const Ring& ring_for(std::string_view equipment, std::string_view sport);

struct ImpactSoundInput {
  double contact_time = 0.0;     ///< s the ball was on the face
  double normal_impulse = 0.0;   ///< N·s
  Ring ring;
};

/// The pulse's spectrum at `hz` against its value at zero (0..1): a half-sine force of
/// duration τ has |F(f)|/|F(0)| = |cos(π f τ)| / |1 − (2 f τ)²|, first zero at 1.5/τ.
double pulse_spectrum_ratio(double hz, double contact_time);

/// The rate sounds are made and played at, Hz.
inline constexpr int kImpactSampleRate = 48000;

/// Mono samples in [−1, 1] at `sample_rate` Hz, `seconds` long: the click, then the ring.
/// Louder with a larger force: full scale is reached near a 120 mph drive. Deterministic.
std::vector<float> synthesize_impact(const ImpactSoundInput& in, int sample_rate = kImpactSampleRate, double seconds = 0.6);

/// The input for a shot's strike (its impact, club or bat); `ok` false when the shot had no
/// strike or no contact time (a launch-only shot or the instantaneous model).
struct ShotSound {
  bool ok = false;
  ImpactSoundInput input;
};
ShotSound impact_sound_of(const ShotResult& shot);

/// 16-bit PCM mono WAV bytes of `samples` at `sample_rate` Hz.
std::string wav_bytes(const std::vector<float>& samples, int sample_rate);

/// `shot --sound`: the shot's strike as a WAV at kImpactSampleRate, written atomically.
/// Throws InputError naming `flag` when the shot has no strike with a contact time.
void write_impact_wav(const ShotResult& shot, const std::filesystem::path& path, const char* flag);

}  // namespace sweetspot
