#include "game/rules/baseball_rules.hpp"

#include <cmath>

namespace sweetspot {

BaseballShotRules::BaseballShotRules(const WorldAsset* world, const ShotModel& model)
    : world_(world),
      model_(model),
      field_level_(default_fairway(), model.terrain->reference_height()),
      field_model_(model) {
  field_model_.terrain = &field_level_;
}

std::optional<Vec3> BaseballShotRules::fence_crossing(const ShotState& before, const ShotState& after,
                                                      const Vec3& v_end) const {
  if (world_ == nullptr || world_->fence_line.size() < 2) return std::nullopt;
  const Vec3 from = before.position(), to = after.position();
  const auto cross2 = [](double ax, double az, double bx, double bz) { return ax * bz - az * bx; };
  const double rx = to.x() - from.x(), rz = to.z() - from.z();
  const Vec3 o = world_->description().origin;
  // Outward: the end is farther from home plate than the start.
  if (!(std::hypot(to.x() - o.x(), to.z() - o.z()) > std::hypot(from.x() - o.x(), from.z() - o.z()))) return std::nullopt;
  const auto& line = world_->fence_line;
  for (size_t i = 0; i + 1 < line.size(); ++i) {
    const Vec3& a = line[i];
    const Vec3& b = line[i + 1];
    const double sx = b.x() - a.x(), sz = b.z() - a.z();
    const double den = cross2(rx, rz, sx, sz);
    if (den == 0.0) continue;
    const double qx = a.x() - from.x(), qz = a.z() - from.z();
    const double t = cross2(qx, qz, sx, sz) / den;  // along the flight segment
    const double u = cross2(qx, qz, rx, rz) / den;  // along the fence segment
    if (t < 0.0 || t > 1.0 || u < 0.0 || u > 1.0) continue;
    // The chord's crossing fraction, refined to the curved path's time by one step of the
    // path's own Hermite interpolation (the xz path is nearly straight over one step).
    const double tc = before.t + t * (after.t - before.t);
    return flight_position_between(from, before.velocity(), before.t, to, v_end, after.t, tc);
  }
  return std::nullopt;
}

bool BaseballShotRules::observe(const ShotState& before, const ShotState& after, const ShotEvent& ev) {
  const bool airborne = before.phase == Phase::Flight || before.phase == Phase::Bounce;
  const bool touched = ev.kind == ShotEventKind::Landing || ev.kind == ShotEventKind::Bounce ||
                       ev.kind == ShotEventKind::Roll;
  if (!home_run_ && !before.landed && airborne) {
    if (const auto at = fence_crossing(before, after, touched ? ev.velocity_in : after.velocity())) {
      // Above the fence top: cleared it (below it, the ball met the wall mesh instead).
      if (at->y() - model_.ball.radius >= world_->description().origin.y() + world_->fence_height) {
        home_run_ = true;
        // Landed beyond the fence in this very step: the play is over.
        return after.landed;
      }
    }
  }
  if (home_run_) return ev.kind == ShotEventKind::Landing || ev.kind == ShotEventKind::Bounce;
  const auto stands = [&](const SurfaceContact& c) {
    return model_.terrain->material(c.material).kind == SurfaceKind::OutOfBounds;
  };
  const bool rolling = after.phase == Phase::Roll || after.phase == Phase::Rest;
  if ((touched && stands(ev.contact)) || (rolling && stands(after.support))) {
    dead_ball_ = true;
    return true;
  }
  return false;
}

ShotEnd BaseballShotRules::outcome(const ShotState& last) const {
  if (home_run_) return ShotEnd::HomeRun;
  if (dead_ball_) return ShotEnd::OutOfBounds;
  if (last.ended && last.end == EndReason::LeftWorld) return ShotEnd::OutOfBounds;
  if (last.ended && last.end == EndReason::StepLimit) return ShotEnd::StepLimit;
  return ShotEnd::Rest;
}

}  // namespace sweetspot
