// Impact-solver micro-benchmark. See impact_bench.hpp.
#include "game/bench/impact_bench.hpp"

#include <chrono>

#include "game/content/equipment_file.hpp"
#include "physics/delivery.hpp"

namespace sweetspot {

std::vector<ImpactInput> realistic_impacts(const EquipmentCatalog& eq) {
  std::vector<ImpactInput> out;
  for (const ClubSpec& club : eq.clubs) {
    for (double speed : {35.0, 45.0, 52.0}) {
      for (double toe : {-0.015, 0.0, 0.01}) {
        for (double up : {-0.008, 0.0, 0.006}) {
          GolfSwing s;
          s.club_speed = speed;
          s.attack_angle = deg_to_rad(-3.0);
          s.impact_toe = toe;
          s.impact_up = up;
          s.face_angle = deg_to_rad(toe * 100.0);  // ±1.5°: vary the face too
          s.club_path = deg_to_rad(-up * 200.0);
          out.push_back(deliver_golf(eq.ball("tour"), club, s, club.face).impact_input);
        }
      }
    }
  }
  for (const BatSpec& bat : eq.bats) {
    for (double from_tip : {0.05, 0.1524, 0.25}) {
      for (double undercut : {-0.02, 0.0, 0.01, 0.025}) {
        BatSwing s;
        s.impact_from_tip = from_tip;
        s.undercut = undercut;
        out.push_back(deliver_baseball(eq.ball("mlb"), bat, s, Pitch{}, bat.material).impact_input);
      }
    }
  }
  return out;
}

double measure_impact_solves_per_s(const EquipmentCatalog& equipment, double min_seconds) {
  const std::vector<ImpactInput> impacts = realistic_impacts(equipment);
  using clock = std::chrono::steady_clock;
  volatile double sink = 0.0;
  double checksum = 0.0;
  long long solves = 0;
  const auto start = clock::now();
  double elapsed = 0.0;
  do {
    for (int rep = 0; rep < 16; ++rep) {
      for (const ImpactInput& in : impacts) {
        const ImpactResult r = solve_impact(in);
        checksum += r.ball_after.velocity.x() + r.ball_after.angular_velocity.z() + r.energy_loss;
      }
    }
    solves += 16 * static_cast<long long>(impacts.size());
    elapsed = std::chrono::duration<double>(clock::now() - start).count();
  } while (elapsed < min_seconds);
  sink = checksum;
  (void)sink;
  return static_cast<double>(solves) / elapsed;
}

}  // namespace sweetspot
