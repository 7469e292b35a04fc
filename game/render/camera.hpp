// Cameras for a shot (pure math, no GL): behind the ball, side, top, follow. Every kind
// but Follow frames the whole shot from the trajectory's bounds, so the default view shows
// launch, apex, landing and rest. World frame of DESIGN §2 (x downrange, y up, z right).
#pragma once

#include <optional>
#include <string_view>
#include <vector>

#include <Eigen/Core>

#include "physics/math.hpp"
#include "physics/trajectory.hpp"

namespace sweetspot {

enum class CameraKind {
  Behind,  ///< behind and above the launch point, looking down the shot line (TV tracer view)
  Side,    ///< from the right (+z) of the shot, downrange to the right of the image
  Top,     ///< from above, downrange up the image, right of the target line to the right
  Follow,  ///< chases the ball at the given time, a few metres behind and above it
};

/// Parses behind|side|top|follow; throws InputError listing the allowed names.
CameraKind parse_camera_kind(std::string_view name);
const char* to_string(CameraKind k);

/// A pinhole camera. Pixel coordinates have their origin at the top-left of the image,
/// x right, y down, pixel centres at +0.5.
struct Camera {
  Vec3 eye{-10.0, 3.0, 0.0};  ///< m
  Vec3 target{0.0, 0.0, 0.0}; ///< m, the point at the image centre
  Vec3 up{0.0, 1.0, 0.0};     ///< approximate up; orthogonalised
  double fov_y = deg_to_rad(45.0);  ///< rad, vertical field of view
  double near_m = 0.5, far_m = 5000.0;

  Vec3 forward() const;  ///< unit, eye -> target
  Vec3 right() const;    ///< unit, image +x
  Vec3 true_up() const;  ///< unit, image -y
  /// OpenGL view and projection matrices (clip z in [-1, 1]).
  Eigen::Matrix4d view() const;
  Eigen::Matrix4d projection(double aspect) const;
  /// Pixel position of world point p in a width x height image; nothing if p is behind
  /// the near plane.
  std::optional<Eigen::Vector2d> project(const Vec3& p, int width, int height) const;
  /// World size (m) of one pixel at the depth of p, for screen-constant line widths.
  double metres_per_pixel(const Vec3& p, int height) const;
};

/// The horizontal unit direction `aim` rad right of the world's +x (ShotResult::aim).
Vec3 aim_line(double aim);

/// Axis-aligned box around a shot: every trajectory sample and the launch point.
struct Bounds {
  Vec3 min = Vec3::Zero(), max = Vec3::Zero();
  void add(const Vec3& p);
  Vec3 centre() const { return 0.5 * (min + max); }
};
Bounds shot_bounds(const ShotTrajectory& trajectory);

/// What a camera frames: the points that must be in view, the launch point, the horizontal
/// shot direction and the ball at the time shown.
struct ShotFraming {
  std::vector<Vec3> points;           ///< m; trajectory samples (decimated is fine)
  Vec3 launch = Vec3::Zero();         ///< m
  Vec3 aim = Vec3::UnitX();           ///< unit, horizontal: launch -> rest (or +x); Follow uses it at rest
  /// unit, horizontal: launch -> first landing (or `aim`): the way the ball came down, which
  /// the landing view looks along. A ball that rebounds off a tree or a wall can rest beside
  /// or behind where it came from; the landing is still ahead of it.
  Vec3 landing_aim = Vec3::UnitX();
  /// unit, horizontal: the line the shot was aimed down (a range's is the world's +x).
  /// Behind, Side and Top look along it, not along this shot, so a push, a pull or a
  /// slice shows as a start or a curve away from the line.
  Vec3 target_line = Vec3::UnitX();
  /// rad: how far Side looks down: 10° from the ground, more over the trees between it and
  /// the flight (ShotScene::camera).
  double side_down = 0.17453292519943295;
  Vec3 ball = Vec3::Zero();           ///< m, ball centre at the time shown
  Vec3 ball_velocity = Vec3::Zero();  ///< m/s at the time shown (Follow looks along it)
  /// s since the first landing at the time shown (negative before it); -1e9 when the shot
  /// never lands. Follow turns from chasing the ball to the landing area in the last second
  /// before the landing.
  double since_landing = -1e9;
  /// m; what the landing view frames: the descending leg (the last third of the flight's
  /// time) and every sample after the landing up to the time shown.
  std::vector<Vec3> finish;
};
ShotFraming shot_framing(const ShotTrajectory& trajectory, double t);

/// The part of the image a framing must keep the shot in, as fractions of its width and
/// height from the top-left: a view that draws panels over its image frames the shot beside
/// them (the batting cage's HUD covers the top-left of its view). The whole image by default.
struct FrameWindow {
  double left = 0.0, top = 0.0, right = 1.0, bottom = 1.0;
};

/// The camera of `kind` for a width x height image. Behind, Side and Top keep every framing
/// point inside the image with a margin of about 8 % per side. Top lays the shot's long
/// axis along the image's long axis (downrange to the right in a landscape image when the
/// shot is longer than wide, up the image otherwise). Behind stands a little to the right
/// of the line so a straight shot's rising and falling legs do not overlap. Follow chases
/// the ball in the air and, in the last second before the landing, turns to frame the landing
/// area (the descending leg, the bounces and the ball).
/// Behind keeps the points inside `window` instead (with the same margin of it); the other
/// kinds frame the whole image.
Camera frame_shot(CameraKind kind, const ShotFraming& framing, int width, int height, const FrameWindow& window = {});

/// The camera a fraction w (0..1) of the way from a to b: eye, target, up and field of view
/// interpolated, w eased at both ends by the caller (ease_in_out). For a smooth cut between
/// cameras; w = 1 is b exactly.
Camera blend_cameras(const Camera& a, const Camera& b, double w);

/// Smoothstep: 0 at x <= 0, 1 at x >= 1, zero slope at both ends.
double ease_in_out(double x);

/// Convenience: frame_shot(kind, shot_framing(trajectory, t), width, height).
Camera frame_shot(CameraKind kind, const ShotTrajectory& trajectory, double t, int width, int height);

/// Ball centre and velocity at time t (s), linear between samples, clamped to the shot.
/// `index` (optional) gets the index of the last sample at or before t.
TrajectorySample sample_at(const ShotTrajectory& trajectory, double t, std::size_t* index = nullptr);

}  // namespace sweetspot
