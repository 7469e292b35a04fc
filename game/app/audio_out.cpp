#include "game/app/audio_out.hpp"

#include <AL/al.h>
#include <AL/alc.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <string>

namespace sweetspot {
namespace {
// More strikes at once than anyone hears apart: the oldest is dropped for the newest.
constexpr std::size_t kMaxVoices = 16;

// Whether this machine has anything to play sound on: a sound server's socket (PulseAudio,
// PipeWire) or an ALSA playback device. Asking OpenAL on a machine with neither makes ALSA
// print its failed configuration search to stderr; a machine without sound is not an error.
bool sound_output_present() {
  namespace fs = std::filesystem;
  std::error_code ec;
  // A user who chose OpenAL's backends (ALSOFT_DRIVERS, e.g. its "wave" file writer) knows.
  if (std::getenv("PULSE_SERVER") != nullptr || std::getenv("ALSOFT_DRIVERS") != nullptr) return true;
  if (const char* run = std::getenv("XDG_RUNTIME_DIR")) {
    const fs::path r(run);
    if (fs::exists(r / "pulse" / "native", ec) || fs::exists(r / "pipewire-0", ec)) return true;
  }
  for (fs::directory_iterator it("/dev/snd", ec), end; !ec && it != end; it.increment(ec)) {
    const std::string name = it->path().filename().string();
    if (name.starts_with("pcm") && name.ends_with("p")) return true;  // pcmC0D0p: a playback device
  }
  return false;
}
}  // namespace

AudioOut::AudioOut(bool enabled) {
  if (!enabled || !sound_output_present()) return;
  // openal-soft logs a missing device as an error on stderr; a machine without sound is not
  // an error for a game. A log level the user set is kept.
  setenv("ALSOFT_LOGLEVEL", "0", 0);
  ALCdevice* dev = alcOpenDevice(nullptr);
  if (!dev) return;
  ALCcontext* ctx = alcCreateContext(dev, nullptr);
  if (!ctx || alcMakeContextCurrent(ctx) != ALC_TRUE) {
    if (ctx) alcDestroyContext(ctx);
    alcCloseDevice(dev);
    return;
  }
  device_ = dev;
  context_ = ctx;
}

AudioOut::~AudioOut() {
  if (!context_) return;
  for (const Voice& v : voices_) free_voice(v);
  if (ambience_.source != 0) free_voice(ambience_);
  alcMakeContextCurrent(nullptr);
  alcDestroyContext(static_cast<ALCcontext*>(context_));
  alcCloseDevice(static_cast<ALCdevice*>(device_));
}

void AudioOut::collect() {
  if (!context_) return;
  std::erase_if(voices_, [](const Voice& v) {
    ALint state = AL_STOPPED;
    alGetSourcei(v.source, AL_SOURCE_STATE, &state);
    if (state == AL_PLAYING) return false;
    alDeleteSources(1, &v.source);
    alDeleteBuffers(1, &v.buffer);
    return true;
  });
}

void AudioOut::free_voice(const Voice& v) {
  alSourceStop(v.source);
  alDeleteSources(1, &v.source);
  alDeleteBuffers(1, &v.buffer);
}

bool AudioOut::make_voice(const std::vector<float>& samples, int rate, Voice& v) {
  std::vector<std::int16_t> pcm(samples.size());
  std::transform(samples.begin(), samples.end(), pcm.begin(), [](float x) {
    return static_cast<std::int16_t>(std::lround(std::clamp(static_cast<double>(x), -1.0, 1.0) * 32767.0));
  });
  alGetError();
  alGenBuffers(1, &v.buffer);
  alBufferData(v.buffer, AL_FORMAT_MONO16, pcm.data(), static_cast<ALsizei>(pcm.size() * sizeof(std::int16_t)), rate);
  alGenSources(1, &v.source);
  alSourcei(v.source, AL_BUFFER, static_cast<ALint>(v.buffer));
  if (alGetError() != AL_NO_ERROR) {  // out of sources or memory: this sound stays silent
    alDeleteSources(1, &v.source);
    alDeleteBuffers(1, &v.buffer);
    return false;
  }
  return true;
}

void AudioOut::play(const std::vector<float>& samples, int rate) {
  if (!context_ || samples.empty() || rate <= 0) return;
  collect();
  if (voices_.size() >= kMaxVoices) {
    free_voice(voices_.front());
    voices_.erase(voices_.begin());
  }
  Voice v;
  if (!make_voice(samples, rate, v)) return;
  alSourcePlay(v.source);
  voices_.push_back(v);
}

void AudioOut::loop(const std::vector<float>& samples, int rate) {
  if (!context_) return;
  if (ambience_.source != 0) free_voice(ambience_);
  ambience_ = Voice{};
  if (samples.empty() || rate <= 0) return;
  Voice v;
  if (!make_voice(samples, rate, v)) return;
  alSourcei(v.source, AL_LOOPING, AL_TRUE);
  alSourcePlay(v.source);
  ambience_ = v;
}

}  // namespace sweetspot
