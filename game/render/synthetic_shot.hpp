// A deterministic, analytic stand-in for a golf drive — NOT physics: a drag-free arc scaled
// to a given carry and apex, two bounces and a roll, with phases set. The render tests,
// the golden image and the frame benchmark use it so their images do not change when the
// flight model changes.
#pragma once

#include "physics/trajectory.hpp"

namespace sweetspot {

struct SyntheticShotSpec {
  double carry = 230.0;     ///< m, first landing distance along x
  double apex = 30.0;       ///< m, max height of the flight arc
  double lateral = 8.0;     ///< m, z at landing (+ right), reached as a smooth curve
  double ball_radius = 0.021335;  ///< m, ball centre height at launch and on the ground
  double ground_y = 0.0;    ///< m, ground height (flat)
};

ShotTrajectory synthetic_shot(const SyntheticShotSpec& spec = {});

}  // namespace sweetspot
