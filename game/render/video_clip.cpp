#include "game/render/video_clip.hpp"

extern "C" {
#include <libavcodec/avcodec.h>
#include <libavformat/avformat.h>
#include <libavutil/opt.h>
#include <libswscale/swscale.h>
}

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>

#include "game/render/render_error.hpp"
#include "game/util/atomic_file.hpp"
#include "physics/error.hpp"

namespace sweetspot {

double clip_seconds(const ClipTiming& c) {
  const double slowed = std::max(0.0, std::min(c.end, kSlowTo) - std::max(c.start, kSlowFrom));
  return (c.end - c.start) + (c.slow - 1.0) * slowed;
}

std::vector<double> clip_frame_times(const ClipTiming& c) {
  if (c.fps < 1 || c.fps > 240) throw InputError("--fps " + std::to_string(c.fps) + ": allowed 1..240");
  if (!(c.slow >= 1.0 && c.slow <= 1000.0)) throw InputError("--slow-motion " + std::to_string(c.slow) + ": allowed 1..1000");
  if (!(c.end >= c.start)) throw InputError("video: the shot ends before it starts");
  const double length = clip_seconds(c);
  const double n = std::ceil(length * c.fps - 1e-9);
  if (n > static_cast<double>(kMaxClipFrames))
    throw InputError("video: " + std::to_string(static_cast<long long>(n)) + " frames; at most " +
                     std::to_string(kMaxClipFrames) + " (lower --fps or --slow-motion)");
  // Clip time runs at 1/slow of the shot's inside the slowed stretch, at its pace outside.
  const double a = std::clamp(kSlowFrom, c.start, c.end), b = std::clamp(kSlowTo, c.start, c.end);
  const double before = a - c.start, slowed = (b - a) * c.slow;
  std::vector<double> t;
  const std::size_t frames = std::max<std::size_t>(1, static_cast<std::size_t>(n));
  t.reserve(frames);
  for (std::size_t k = 0; k < frames; ++k) {
    const double u = static_cast<double>(k) / c.fps;
    double s = u <= before ? c.start + u : u <= before + slowed ? a + (u - before) / c.slow : b + (u - before - slowed);
    t.push_back(std::min(s, c.end));
  }
  return t;
}

// The MP4 is built in memory (the muxer seeks back to write its index), then written at once.
struct Mp4Bytes {
  std::string bytes;
  std::int64_t pos = 0;
};

namespace {

std::string av_message(int err) {
  char buf[AV_ERROR_MAX_STRING_SIZE] = {0};
  av_strerror(err, buf, sizeof buf);
  return buf;
}

int write_packet(void* opaque, std::uint8_t* data, int size) {
  auto* f = static_cast<Mp4Bytes*>(opaque);
  const std::size_t end = static_cast<std::size_t>(f->pos) + static_cast<std::size_t>(size);
  if (f->bytes.size() < end) f->bytes.resize(end);
  std::memcpy(f->bytes.data() + f->pos, data, static_cast<std::size_t>(size));
  f->pos = static_cast<std::int64_t>(end);
  return size;
}

std::int64_t seek(void* opaque, std::int64_t offset, int whence) {
  auto* f = static_cast<Mp4Bytes*>(opaque);
  const auto size = static_cast<std::int64_t>(f->bytes.size());
  switch (whence & ~AVSEEK_FORCE) {
    case AVSEEK_SIZE: return size;
    case SEEK_SET: f->pos = offset; break;
    case SEEK_CUR: f->pos += offset; break;
    case SEEK_END: f->pos = size + offset; break;
    default: return -1;
  }
  if (f->pos < 0) f->pos = 0;
  return f->pos;
}

}  // namespace

struct Mp4Writer::Impl {
  Mp4Bytes file;
  AVFormatContext* fmt = nullptr;
  AVCodecContext* codec = nullptr;
  AVStream* stream = nullptr;
  AVFrame* frame = nullptr;
  AVPacket* packet = nullptr;
  SwsContext* sws = nullptr;
  unsigned char* io_buffer = nullptr;
  AVIOContext* io = nullptr;

  ~Impl() {
    sws_freeContext(sws);
    av_packet_free(&packet);
    av_frame_free(&frame);
    avcodec_free_context(&codec);
    if (io) {
      av_freep(&io->buffer);
      avio_context_free(&io);
    } else {
      av_free(io_buffer);
    }
    if (fmt) fmt->pb = nullptr;
    avformat_free_context(fmt);
  }

  void check(int err, const char* what) const {
    if (err < 0) throw RenderError(std::string("video: ") + what + ": " + av_message(err));
  }

  // Sends `f` (nullptr: the end) and writes every packet the encoder has ready.
  void encode(AVFrame* f) {
    check(avcodec_send_frame(codec, f), "encoding a frame");
    for (;;) {
      const int r = avcodec_receive_packet(codec, packet);
      if (r == AVERROR(EAGAIN) || r == AVERROR_EOF) return;
      check(r, "encoding a frame");
      packet->duration = 1;  // one frame: the last frame counts in the file's duration
      av_packet_rescale_ts(packet, codec->time_base, stream->time_base);
      packet->stream_index = stream->index;
      check(av_interleaved_write_frame(fmt, packet), "writing a frame");
    }
  }
};

Mp4Writer::Mp4Writer(int width, int height, int fps) : impl_(new Impl), width_(width), height_(height) {
  Impl& m = *impl_;
  av_log_set_level(AV_LOG_ERROR);  // libx264's settings summary is not the user's business
  try {
    if (width < 16 || height < 16 || width % 2 != 0 || height % 2 != 0)
      throw InputError("video: " + std::to_string(width) + "x" + std::to_string(height) +
                       " px; H.264 needs even sizes of at least 16 (--width, --height)");
    m.check(avformat_alloc_output_context2(&m.fmt, nullptr, "mp4", nullptr), "the MP4 muxer");
    // libx264 where libavcodec has it (Debian's does), else whatever H.264 encoder it has.
    const AVCodec* enc = avcodec_find_encoder_by_name("libx264");
    if (!enc) enc = avcodec_find_encoder(AV_CODEC_ID_H264);
    if (!enc) throw RenderError("video: this libavcodec has no H.264 encoder (Debian's libavcodec59 has libx264)");
    m.stream = avformat_new_stream(m.fmt, nullptr);
    m.codec = avcodec_alloc_context3(enc);
    if (!m.stream || !m.codec) throw RenderError("video: out of memory");
    m.codec->width = width;
    m.codec->height = height;
    m.codec->time_base = AVRational{1, fps};
    m.codec->framerate = AVRational{fps, 1};
    m.codec->pix_fmt = AV_PIX_FMT_YUV420P;
    m.codec->gop_size = fps;
    m.codec->thread_count = 1;  // the same bytes on every run
    if (m.fmt->oformat->flags & AVFMT_GLOBALHEADER) m.codec->flags |= AV_CODEC_FLAG_GLOBAL_HEADER;
    av_opt_set(m.codec->priv_data, "preset", "veryfast", 0);
    av_opt_set(m.codec->priv_data, "crf", "20", 0);
    m.check(avcodec_open2(m.codec, enc, nullptr), "opening the H.264 encoder");
    m.check(avcodec_parameters_from_context(m.stream->codecpar, m.codec), "the stream's parameters");
    m.stream->time_base = m.codec->time_base;
    constexpr int kIoBuffer = 1 << 16;
    m.io_buffer = static_cast<unsigned char*>(av_malloc(kIoBuffer));
    if (!m.io_buffer) throw RenderError("video: out of memory");
    m.io = avio_alloc_context(m.io_buffer, kIoBuffer, 1, &m.file, nullptr, write_packet, seek);
    if (!m.io) throw RenderError("video: out of memory");
    m.io_buffer = nullptr;  // the context owns it now
    m.fmt->pb = m.io;
    m.fmt->flags |= AVFMT_FLAG_CUSTOM_IO;
    m.check(avformat_write_header(m.fmt, nullptr), "the MP4 header");
    m.frame = av_frame_alloc();
    m.packet = av_packet_alloc();
    if (!m.frame || !m.packet) throw RenderError("video: out of memory");
    m.frame->format = AV_PIX_FMT_YUV420P;
    m.frame->width = width;
    m.frame->height = height;
    m.check(av_frame_get_buffer(m.frame, 0), "a frame buffer");
    m.sws = sws_getContext(width, height, AV_PIX_FMT_RGBA, width, height, AV_PIX_FMT_YUV420P, SWS_BILINEAR, nullptr,
                           nullptr, nullptr);
    if (!m.sws) throw RenderError("video: no RGBA to YUV 4:2:0 conversion");
  } catch (...) {
    delete impl_;
    throw;
  }
}

Mp4Writer::~Mp4Writer() { delete impl_; }

void Mp4Writer::add_frame(const std::vector<std::uint8_t>& rgba) {
  Impl& m = *impl_;
  if (rgba.size() != static_cast<std::size_t>(width_) * static_cast<std::size_t>(height_) * 4)
    throw RenderError("video: a frame of the wrong size");
  m.check(av_frame_make_writable(m.frame), "a frame buffer");
  const std::uint8_t* src[1] = {rgba.data()};
  const int stride[1] = {4 * width_};
  sws_scale(m.sws, src, stride, 0, height_, m.frame->data, m.frame->linesize);
  m.frame->pts = frames_++;
  m.encode(m.frame);
}

void Mp4Writer::finish(const std::filesystem::path& path) {
  Impl& m = *impl_;
  m.encode(nullptr);
  m.check(av_write_trailer(m.fmt), "the MP4 index");
  avio_flush(m.io);
  write_file_atomic(path, m.file.bytes);
}

}  // namespace sweetspot
