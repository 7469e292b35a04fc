// The ball's trail as camera-facing ribbon triangles, coloured by phase (flight, bounce,
// roll), drawn unlit so its colour in the image is the phase colour. Pure geometry.
#pragma once

#include <Eigen/Core>

#include "game/render/camera.hpp"
#include "game/render/mesh_data.hpp"
#include "physics/trajectory.hpp"

namespace sweetspot {

/// The trail colour of a phase (RGB 0..1): flight yellow, bounce orange, roll magenta.
/// Rest has no trail segment; it returns the roll colour.
Eigen::Vector3f phase_color(Phase phase);

struct TrailStyle {
  double width_px = 5.0;  ///< ribbon width on screen, pixels (the same near and far)
  int image_height = 720; ///< pixels, to turn width_px into metres at each point
  /// TV-tracer halo: a translucent ribbon this wide (px) under the solid core, strongest
  /// at the ball and fading to 40 % of that at the launch; 0 = no halo (typical 18).
  double glow_px = 0.0;
  double glow_opacity = 0.55;  ///< halo opacity at its centre line next to the ball, 0..1
};

/// Appends the trail from launch up to time t (s) to `out`: one quad per sample segment
/// (samples i -> i+1), coloured by the phase of sample i+1 (the motion that produced the
/// segment), widened perpendicular to the line of sight so it faces the camera. The quad is
/// width_px + 1 px wide: flat.frag fades its outer half pixel on each side (vertices carry
/// normal.x = 1 and the across-ribbon coordinate -1..1 in `pattern`). With glow_px > 0 the
/// halo quads come first (drawn under the core): normal.x = 2, normal.y = their opacity,
/// which flat.frag fades to 0 at the halo's edges.
void append_trail(MeshData& out, const ShotTrajectory& trajectory, double t, const Camera& camera,
                  const TrailStyle& style);

}  // namespace sweetspot
