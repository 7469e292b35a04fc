#include "game/modes/golf/swing_meter.hpp"

#include <algorithm>
#include <cmath>

#include "physics/error.hpp"

namespace sweetspot {

double timing_error_ms(const MeterInput& m, const ClubSpec& club) {
  const double over = std::max(0.0, m.power - 1.0);
  return m.accuracy_ms * (club.length / kDriverLength) * (1.0 + 4.0 * over);
}

GolfSwing meter_swing(const MeterInput& m, const ClubSpec& club, const ClubInfo& info, double full_speed) {
  validate_meter(m);
  GolfSwing s;
  s.club_speed = m.power * full_speed;
  s.attack_angle = info.tour_attack;
  if (info.kind == "putter") return s;  // putting: power only; the aim is the line
  const double over = std::max(0.0, m.power - 1.0);
  const double err = timing_error_ms(m, club);
  s.face_angle = std::clamp(kFacePerMs * err, GolfSwing::kFaceAngle.min, GolfSwing::kFaceAngle.max);
  s.club_path = std::clamp(kPathPerMs * err, GolfSwing::kClubPath.min, GolfSwing::kClubPath.max);
  // The worst miss still meets the face, at its edge (the edge is within the swing's ranges).
  const double toe_edge = std::min(club.face_half_width, GolfSwing::kImpactToe.max);
  const double up_edge = std::min(club.face_half_height, GolfSwing::kImpactUp.max);
  s.impact_toe = std::clamp(-kHeelPerMs * err, -toe_edge, toe_edge);
  s.impact_up = std::clamp(club.strike_height - 0.030 * over, -up_edge, up_edge);
  return s;
}

}  // namespace sweetspot
