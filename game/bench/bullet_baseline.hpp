// The way a typical game flies a ball, kept as the benchmark's baseline (DESIGN §8): a
// Bullet btDiscreteDynamicsWorld with a btRigidBody sphere, CCD on, stepped at 60 Hz with
// 240 Hz fixed substeps, aerodynamic forces applied in a pre-tick callback every substep
// (cleared and re-applied, so they don't accumulate across substeps — a classic mistake),
// and landing taken at the first substep whose contact manifold touches the ground.
//
// It is written to be a fair, correct baseline, not a strawman: same aero model, same
// ground mesh, the usual semi-implicit Euler integrator that Bullet uses.
#pragma once

#include <functional>
#include <vector>

#include "physics/launch.hpp"
#include "physics/math.hpp"

namespace sweetspot::bench {

/// Aerodynamic force (N) and spin rate of change (rad/s²) on the ball for a state.
struct AeroEffect {
  Vec3 force = Vec3::Zero();
  Vec3 spin_rate = Vec3::Zero();
};
using AeroFn = std::function<AeroEffect(const Vec3& position, const Vec3& velocity, const Vec3& spin)>;

struct BaselineGround {
  std::vector<Vec3> positions;   ///< m, world frame
  std::vector<int> indices;      ///< 3 per triangle
  double restitution = 0.4;      ///< Bullet multiplies ball × ground restitution
  double friction = 0.5;
  double rolling_friction = 0.02;
};

struct BaselineBall {
  double mass = 0.04593;    ///< kg
  double radius = 0.021335; ///< m
  double inertia = 8.36e-6; ///< kg·m²
};

struct BaselineResult {
  double carry_m = 0.0;     ///< horizontal distance from launch at the first ground contact
  double total_m = 0.0;     ///< horizontal distance at rest (or at the time limit)
  double time_s = 0.0;      ///< simulated time until rest
  long substeps = 0;
  bool landed = false;
};

struct BaselineOptions {
  double frame_dt = 1.0 / 60.0;     ///< s, the game's frame
  double substep_dt = 1.0 / 240.0;  ///< s, Bullet's fixed internal step
  double max_time = 60.0;           ///< s
  double rest_speed = 0.05;         ///< m/s below which the ball is at rest
  bool carry_only = false;          ///< stop at the first landing
};

BaselineResult run_bullet_baseline(const LaunchState& launch, const BaselineBall& ball,
                                   const AeroFn& aero, const BaselineGround& ground,
                                   const BaselineOptions& options = {});

/// The ground's triangle mesh and BVH, built once and shared by many baseline shots (a game
/// builds its level once, not per shot). Not copyable; keep `ground` alive while it lives.
class BaselineGroundShape {
 public:
  explicit BaselineGroundShape(const BaselineGround& ground);
  ~BaselineGroundShape();
  BaselineGroundShape(const BaselineGroundShape&) = delete;
  BaselineGroundShape& operator=(const BaselineGroundShape&) = delete;
  const BaselineGround& ground() const { return ground_; }
  void* shape() const { return shape_; }  ///< btBvhTriangleMeshShape*

 private:
  const BaselineGround& ground_;
  void* mesh_ = nullptr;   // btTriangleMesh*
  void* shape_ = nullptr;  // btBvhTriangleMeshShape*
};

/// The same shot on a prebuilt ground shape.
BaselineResult run_bullet_baseline(const LaunchState& launch, const BaselineBall& ball,
                                   const AeroFn& aero, const BaselineGroundShape& ground,
                                   const BaselineOptions& options = {});

}  // namespace sweetspot::bench
