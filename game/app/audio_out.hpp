// Sound out of the game window (DESIGN §1, app/: audio) through OpenAL. Without an audio
// device, or with --mute, it stays silent: play() does nothing and nothing fails or waits.
#pragma once

#include <vector>

namespace sweetspot {

class AudioOut {
 public:
  /// `enabled` false (--mute): never opens a device.
  explicit AudioOut(bool enabled);
  ~AudioOut();
  AudioOut(const AudioOut&) = delete;
  AudioOut& operator=(const AudioOut&) = delete;

  /// True when a device is open and sound is played.
  bool active() const { return context_ != nullptr; }
  /// Starts mono samples in [−1, 1] at `sample_rate` Hz; they mix with what still plays.
  void play(const std::vector<float>& samples, int sample_rate);
  /// Loops mono `samples` (an ambience) under everything else, in place of the loop before;
  /// empty samples stop it.
  void loop(const std::vector<float>& samples, int sample_rate);
  /// Frees the sounds that have finished (call once a frame).
  void collect();

 private:
  struct Voice {
    unsigned source = 0, buffer = 0;
  };
  /// A source holding `samples`, not yet playing; nothing when OpenAL has no room for it.
  bool make_voice(const std::vector<float>& samples, int sample_rate, Voice& out);
  static void free_voice(const Voice& v);
  Voice ambience_;
  void* device_ = nullptr;
  void* context_ = nullptr;
  std::vector<Voice> voices_;
};

}  // namespace sweetspot
