#include "game/ui/cage_people.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>

#include "game/render/golfer_figure.hpp"

namespace sweetspot {
namespace {

using Stage = BattingCage::Stage;

// Widths of a 1.88 m player's parts (ESTIMATES): a torso ~0.3 m across, limbs ~0.11 m, a
// head ~0.22 m; a bat's barrel 2.6 in (MLB Rule 3.02), drawn a little fuller to read.
constexpr double kTorso = 0.3, kLimb = 0.11, kHeadSize = 0.22, kBat = 0.07;
// The swing from his launch position to contact: ~0.15 s for a major-league hitter
// (swing_pose.hpp's kBatSwing), batter_figure's phase 0.6 to 1.
constexpr double kSwingTime = 0.15;

const Eigen::Vector3f kFielding{0.16f, 0.27f, 0.78f};
const Eigen::Vector3f kBatting{0.92f, 0.92f, 0.90f};
const Eigen::Vector3f kWood{0.76f, 0.56f, 0.32f};

// What the figures need of the cage, by value: a clip draws them on its own thread after
// play has moved on.
struct Cast {
  enum class Clock { Held, Pitch, Batted } clock = Clock::Held;
  double held_now = 0.0, released_at = 0.0, batted_at = 0.0, swung_at = -1e9;
  double scale = BattingCage::kPitchTimeScale;  // the pitch's pace against real time
  Stage stage = Stage::Ready;
  Vec3 release = Vec3::Zero();
  bool pitcher_left = false, batter_left = false, in_play = false, batted = false;
  double bat_height = 0.76, flight_time = 0.4;
  std::array<Vec3, 9> start{}, goal{};
  int fielder = -1;                 // who fields the ball in play
  Vec3 fielded_at = Vec3::Zero();   // the ball where he has it
  double fielded_time = 0.0;        // s after contact

  double mode_time(double t) const {
    switch (clock) {
      case Clock::Pitch: return released_at + t / scale;
      case Clock::Batted: return batted_at + t;
      case Clock::Held: break;
    }
    return held_now;
  }
  double pitch_clock(double now) const { return (now - released_at) * scale; }

  void draw(const PeopleFrame& frame, MeshData& out) const {
    const double now = mode_time(frame.t);
    // The pitcher: set before a pitch, his delivery during it, the follow-through after.
    const double pt = stage == Stage::Ready ? -kWindupTime
                      : stage == Stage::Pitching ? pitch_clock(now)
                                                 : std::min(pitch_clock(now), 0.6);
    append_figure(out, pitcher_figure(release, pt, pitcher_left), frame, kFielding, kWood);
    // The other eight where they stand, or running to the ball once it is hit.
    static const Defense league = league_defense();
    const double since = std::max(0.0, now - batted_at);
    for (std::size_t i = 1; i < 9; ++i) {
      const bool catcher = i == 1;
      if (catcher && !batted) continue;  // crouched between the batter's eye and the plate
      // The one who fields it reaches for the ball as it comes to him (ESTIMATE: from 0.3 s
      // before he has it until 0.4 s after).
      std::optional<Vec3> glove;
      if (in_play && static_cast<int>(i) == fielder && since > fielded_time - 0.3 && since < fielded_time + 0.4)
        glove = fielded_at;
      append_figure(out, fielder_figure(start[i], goal[i], league.ability[i], in_play ? since : 0.0, catcher, glove), frame,
                    kFielding, kWood);
    }
    // The batter: his stride as the pitch comes, the swing, the follow-through he holds
    // until the next pitch.
    double phase = 0.0;
    if (stage == Stage::Pitching) phase = 0.6 * std::clamp(pitch_clock(now) / std::max(flight_time, 1e-6), 0.0, 1.0);
    const bool swung_this_pitch = stage != Stage::Ready && pitch_clock(swung_at) >= 0.0;
    if (swung_this_pitch && now >= swung_at)
      phase = 1.0 + 0.6 * std::clamp((now - swung_at) * scale / 0.25, 0.0, 1.0);
    else if (swung_this_pitch && now >= swung_at - kSwingTime)
      phase = 1.0 - 0.4 * (swung_at - now) / kSwingTime;
    append_figure(out, batter_figure(phase, bat_height, batter_left), frame, kBatting, kWood);
  }
};

}  // namespace

void append_figure(MeshData& out, const Figure& f, const PeopleFrame& frame, const Eigen::Vector3f& body,
                   const Eigen::Vector3f& bat) {
  const auto wide = [&](const Vec3& at, double width, double min_px) {
    if (frame.camera == nullptr || frame.height <= 0) return width;
    return std::max(width, min_px * frame.camera->metres_per_pixel(at, frame.height));
  };
  for (const auto& [a, b] : figure_bones()) {
    const bool is_bat = a == kBatKnob;
    if (is_bat && !f.has_bat) continue;
    const Vec3& pa = f.joint[static_cast<std::size_t>(a)];
    const Vec3& pb = f.joint[static_cast<std::size_t>(b)];
    const bool torso = a == kNeck && b == kPelvis;
    const double width = is_bat ? kBat : torso ? kTorso : kLimb;
    append_limb(out, pa, pb, wide(0.5 * (pa + pb), width, kFigureMinPx), is_bat ? bat : body);
  }
  const Vec3& head = f.joint[kHead];
  const double size = wide(head, kHeadSize, 2.0 * kFigureMinPx);
  append_limb(out, head - Vec3(0.0, 0.5 * size, 0.0), head + Vec3(0.0, 0.5 * size, 0.0), size, body);
}

double cage_scene_time(const BattingCage& c, double now) {
  if (c.batted()) return now - c.batted_at();
  return c.pitch_clock(now);
}

PeopleFn cage_people(const BattingCage& c, double now) {
  Cast cast;
  cast.stage = c.stage();
  cast.held_now = now;
  cast.scale = c.time_scale();
  cast.released_at = now - c.pitch_clock(now) / cast.scale;
  cast.batted_at = c.batted_at();
  cast.swung_at = c.swung_at();
  cast.batted = c.batted();
  cast.clock = cast.batted ? Cast::Clock::Batted : c.stage() == Stage::Pitching ? Cast::Clock::Pitch : Cast::Clock::Held;
  const bool any_pitch = c.stage() != Stage::Ready || !c.swings().empty();
  const PitchType& type = c.call().type;
  // The man on the mound: the next pitch's thrower, at his last release if it was his hand's.
  cast.pitcher_left = c.stage() == Stage::Ready ? c.pitcher_left() : c.call().left_handed;
  cast.release = any_pitch && cast.pitcher_left == c.call().left_handed
                     ? c.pitch().release
                     : Vec3(kRubberToPlate - type.extension, type.release_height, type.release_side);
  cast.batter_left = c.left_handed();
  cast.bat_height = c.bat_height();
  cast.flight_time = c.pitch().flight_time;
  cast.in_play = cast.batted && c.last().result.contact;
  const std::array<Vec3, 9> spots = fielder_spots(c.left_handed());
  const FieldingPlay& play = c.last().result.play;
  for (std::size_t i = 0; i < 9; ++i) {
    cast.start[i] = cast.in_play ? play.start[i] : spots[i];
    cast.goal[i] = cast.in_play ? play.goal[i] : spots[i];
  }
  cast.fielder = play.fielder;
  cast.fielded_at = play.fielded_at;
  cast.fielded_time = play.fielded_time;
  return [cast](const PeopleFrame& frame, MeshData& out) { cast.draw(frame, out); };
}

}  // namespace sweetspot
