// A shot as a video clip (issue 44): which instant of the shot each frame shows, with the
// strike played in slow motion, and the frames written as an H.264 MP4 (libavcodec,
// libavformat, libswscale), atomically like every output.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace sweetspot {

/// The stretch around the strike that slow motion slows: from just before contact until the
/// ball is clear of the face or bat (a 70 m/s ball is ~2.8 m out after 40 ms).
inline constexpr double kSlowFrom = -0.010, kSlowTo = 0.040;  // s of the shot

struct ClipTiming {
  double start = 0.0;  ///< s of the shot at the first frame (before launch: the downswing)
  double end = 0.0;    ///< s of the shot at the last frame
  int fps = 30;
  /// Slow-motion factor over [kSlowFrom, kSlowTo]: 1 = real time, 40 = a 1200 fps camera
  /// played at 30 fps.
  double slow = 1.0;
};

/// The clip's length in seconds: real time, plus (slow − 1) times the slowed stretch.
double clip_seconds(const ClipTiming& c);
/// The shot time of each frame, in order: ceil(clip_seconds · fps) frames, frame k at clip
/// time k/fps, the last no later than `end`. Throws InputError for fps outside 1..240, slow
/// outside 1..1000, end before start, or more than kMaxClipFrames frames.
std::vector<double> clip_frame_times(const ClipTiming& c);
inline constexpr std::size_t kMaxClipFrames = 36000;  ///< 20 min at 30 fps

/// Encodes RGBA8 frames (top row first) as H.264 in an MP4, in memory, then writes it
/// atomically. Width and height must be even (4:2:0 chroma).
class Mp4Writer {
 public:
  Mp4Writer(int width, int height, int fps);
  ~Mp4Writer();
  Mp4Writer(const Mp4Writer&) = delete;
  Mp4Writer& operator=(const Mp4Writer&) = delete;
  void add_frame(const std::vector<std::uint8_t>& rgba);
  /// Flushes the encoder, closes the file and writes it to `path` (atomically).
  void finish(const std::filesystem::path& path);
  int frames() const { return frames_; }

 private:
  struct Impl;
  Impl* impl_;
  int width_, height_, frames_ = 0;
};

}  // namespace sweetspot
