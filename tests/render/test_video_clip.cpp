// Video clips (game/render/video_clip.hpp): which instant each frame shows, slow motion over
// the strike, and the H.264 MP4 read back through libavformat as a player would.
extern "C" {
#include <libavcodec/avcodec.h>
#include <libavformat/avformat.h>
}

#include <unistd.h>

#include <cmath>
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include <catch2/catch.hpp>

#include "game/render/render_command.hpp"
#include "game/render/render_error.hpp"
#include "game/render/swing_pose.hpp"
#include "game/render/synthetic_shot.hpp"
#include "game/render/video_clip.hpp"
#include "physics/error.hpp"
#include "support/test_assets.hpp"

using namespace sweetspot;

namespace {

struct Probe {
  bool h264 = false;
  int width = 0, height = 0;
  int frames = 0;
  double seconds = 0.0;
};

// What a player reads of the file: the codec, the size, every video packet and the duration.
Probe probe(const std::filesystem::path& path) {
  Probe p;
  AVFormatContext* fmt = nullptr;
  REQUIRE(avformat_open_input(&fmt, path.c_str(), nullptr, nullptr) == 0);
  REQUIRE(avformat_find_stream_info(fmt, nullptr) >= 0);
  const int v = av_find_best_stream(fmt, AVMEDIA_TYPE_VIDEO, -1, -1, nullptr, 0);
  REQUIRE(v >= 0);
  const AVCodecParameters* par = fmt->streams[v]->codecpar;
  p.h264 = par->codec_id == AV_CODEC_ID_H264;
  p.width = par->width;
  p.height = par->height;
  p.seconds = static_cast<double>(fmt->duration) / AV_TIME_BASE;
  AVPacket* pkt = av_packet_alloc();
  while (av_read_frame(fmt, pkt) >= 0) {
    if (pkt->stream_index == v) ++p.frames;
    av_packet_unref(pkt);
  }
  av_packet_free(&pkt);
  avformat_close_input(&fmt);
  return p;
}

std::filesystem::path temp_path(const char* name) {
  return std::filesystem::temp_directory_path() / (std::string("sweetspot_test_") + std::to_string(::getpid()) + "_" + name);
}

}  // namespace

TEST_CASE("a real-time clip shows the shot at the frame rate", "[video]") {
  const ClipTiming c{-0.25, 2.0, 30, 1.0};
  CHECK(clip_seconds(c) == Approx(2.25));
  const std::vector<double> t = clip_frame_times(c);
  REQUIRE(t.size() == 68);  // ceil(2.25 s * 30)
  CHECK(t.front() == Approx(-0.25));
  for (std::size_t k = 1; k < t.size(); ++k) CHECK(t[k] - t[k - 1] == Approx(1.0 / 30.0).margin(1e-12));
  CHECK(t.back() <= 2.0);
}

TEST_CASE("slow motion stretches the strike, and only the strike", "[video]") {
  const ClipTiming c{-0.25, 2.0, 30, 40.0};
  // 2.25 s of shot, of which the 50 ms from 10 ms before contact to 40 ms after last 40 times longer.
  CHECK(clip_seconds(c) == Approx(2.25 + 39.0 * 0.050));
  const std::vector<double> t = clip_frame_times(c);
  REQUIRE(t.size() == static_cast<std::size_t>(std::ceil(clip_seconds(c) * 30.0 - 1e-9)));
  int slowed = 0, after_contact = 0;
  for (std::size_t k = 1; k < t.size(); ++k) {
    const double step = t[k] - t[k - 1];
    CHECK(step > 0.0);
    if (t[k - 1] >= kSlowFrom && t[k] <= kSlowTo) {
      CHECK(step == Approx(1.0 / (30.0 * 40.0)).margin(1e-12));
      ++slowed;
    }
    if (t[k] > 0.0 && t[k] <= 0.010) ++after_contact;
  }
  CHECK(slowed >= 58);
  // A ball leaves a driver's face at ~70 m/s: the first 10 ms (0.7 m of flight) take 12 frames.
  CHECK(after_contact >= 11);
  CHECK(t.back() <= 2.0);
  // A shot that ends inside the slowed stretch slows only what there is of it.
  CHECK(clip_seconds(ClipTiming{-0.005, 0.015, 30, 10.0}) == Approx(0.020 * 10.0));
}

TEST_CASE("a clip refuses what it cannot make, naming the flag", "[video]") {
  CHECK_THROWS_WITH(clip_frame_times(ClipTiming{0.0, 1.0, 0, 1.0}), Catch::Contains("--fps"));
  CHECK_THROWS_WITH(clip_frame_times(ClipTiming{0.0, 1.0, 241, 1.0}), Catch::Contains("--fps"));
  CHECK_THROWS_WITH(clip_frame_times(ClipTiming{0.0, 1.0, 30, 0.5}), Catch::Contains("--slow-motion"));
  CHECK_THROWS_WITH(clip_frame_times(ClipTiming{0.0, 1.0, 30, std::nan("")}), Catch::Contains("--slow-motion"));
  CHECK_THROWS_WITH(clip_frame_times(ClipTiming{0.0, 3600.0, 30, 1.0}), Catch::Contains("frames"));
  CHECK_THROWS_AS(Mp4Writer(65, 48, 30), InputError);
  CHECK_THROWS_AS(Mp4Writer(8, 8, 30), InputError);
}

TEST_CASE("the MP4 holds every frame as H.264 and lasts frames / fps", "[video]") {
  const int w = 64, h = 48, fps = 12, n = 18;
  Mp4Writer writer(w, h, fps);
  for (int k = 0; k < n; ++k) {
    std::vector<std::uint8_t> rgba(static_cast<std::size_t>(w * h * 4), 255);
    for (int i = 0; i < w * h; ++i) rgba[static_cast<std::size_t>(4 * i)] = static_cast<std::uint8_t>(k * 14);
    writer.add_frame(rgba);
  }
  CHECK_THROWS_AS(writer.add_frame(std::vector<std::uint8_t>(10)), RenderError);
  const auto path = temp_path("frames.mp4");
  writer.finish(path);
  const Probe p = probe(path);
  std::filesystem::remove(path);
  CHECK(p.h264);
  CHECK(p.width == w);
  CHECK(p.height == h);
  CHECK(p.frames == n);
  CHECK(p.seconds == Approx(static_cast<double>(n) / fps).margin(0.002));
}

TEST_CASE("a shot's clip from the downswing to its end, the strike in slow motion", "[video][render]") {
  RenderRequest r;
  r.assets = &test::assets();
  r.world = nullptr;
  r.tee = true;
  r.impactor_mesh = "driver_head";
  ImpactorPlacement club;
  club.position = Vec3(-0.0214, 0.0214, 0.0);
  r.impactor = club;
  r.width = 96;
  r.height = 64;
  const ShotTrajectory shot = synthetic_shot();
  const auto path = temp_path("shot.mp4");
  int frames = 0;
  try {
    frames = render_shot_video(shot, r, VideoRequest{10, 20.0}, path);
  } catch (const RenderUnavailable& e) {
    WARN("no EGL here: " << e.what());
    return;
  }
  const Probe p = probe(path);
  std::filesystem::remove(path);
  const ClipTiming c{-swing_pre_roll(r.impactor, r.impactor_mesh), shot.samples.back().t, 10, 20.0};
  CHECK(frames == static_cast<int>(clip_frame_times(c).size()));
  CHECK(p.frames == frames);
  CHECK(p.seconds == Approx(static_cast<double>(frames) / 10.0).margin(0.002));
  CHECK(p.width == 96);
  CHECK(p.height == 64);
}
