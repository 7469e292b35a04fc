// Calibration against the TrackMan PGA Tour averages of DESIGN §4: the default equipment,
// each club's documented dynamic loft and the tour club speed and attack angle reproduce
// ball speed within 3 %, launch angle within 1.5° and spin within 15 %. One physical model
// for every club: the same ball, the same ball–face contact law (µ, e_t and its speed
// fade, friction model), only measured or documented per-club data (loft, mass, CG,
// inertia, face COR) differ.
#include <catch2/catch.hpp>

#include "game/content/equipment_file.hpp"
#include "support/test_assets.hpp"
#include "physics/delivery.hpp"
#include "physics/units.hpp"

using namespace sweetspot;

namespace {
struct TrackManRow {
  const char* club;
  double club_mph, attack_deg, ball_mph, launch_deg, spin_rpm;
};
constexpr TrackManRow kRows[] = {
    {"driver", 113, -1.3, 167, 10.9, 2686},
    {"7-iron", 90, -4.3, 120, 16.3, 7097},
    {"pw", 83, -5.0, 102, 24.2, 9304},
};
}  // namespace

TEST_CASE("tour deliveries reproduce the TrackMan PGA averages", "[delivery][calibration]") {
  const EquipmentCatalog& eq = test::assets().equipment();
  const BallSpec& ball = eq.ball("tour");
  for (const TrackManRow& row : kRows) {
    const ClubSpec& club = eq.club(row.club);
    GolfSwing s;
    s.club_speed = mph_to_mps(row.club_mph);
    s.attack_angle = deg_to_rad(row.attack_deg);
    const Delivery d = deliver_golf(ball, club, s, club.face);
    const LaunchMetrics m = measure_launch(d.launch);
    INFO(row.club << ": ball " << mps_to_mph(m.ball_speed) << " mph (TrackMan " << row.ball_mph << "), launch "
                  << rad_to_deg(m.vertical_angle) << " deg (" << row.launch_deg << "), spin "
                  << radps_to_rpm(m.spin.total) << " rpm (" << row.spin_rpm << "), dynamic loft "
                  << rad_to_deg(club.dynamic_loft) << " deg, smash " << d.smash_factor);
    CHECK(mps_to_mph(m.ball_speed) == Approx(row.ball_mph).epsilon(0.03));
    CHECK(rad_to_deg(m.vertical_angle) == Approx(row.launch_deg).margin(1.5));
    CHECK(radps_to_rpm(m.spin.total) == Approx(row.spin_rpm).epsilon(0.15));
    CHECK(std::abs(rad_to_deg(m.horizontal_angle)) < 0.5);
    CHECK(std::abs(rad_to_deg(m.spin.axis_rad)) < 3.0);
  }
}

TEST_CASE("one contact model for every club: no per-club friction or spin factor", "[delivery][calibration]") {
  const EquipmentCatalog& eq = test::assets().equipment();
  const ImpactMaterial& ref = eq.club("driver").face;
  for (const ClubSpec& c : eq.clubs) {
    INFO(c.name);
    CHECK(c.face.mu == ref.mu);
    CHECK(c.face.e_t == ref.e_t);
    CHECK(c.face.friction == ref.friction);
    CHECK(c.face.e_t_scale.count == ref.e_t_scale.count);
    for (int i = 0; i < ref.e_t_scale.count; ++i) {
      CHECK(c.face.e_t_scale.speed[static_cast<size_t>(i)] == ref.e_t_scale.speed[static_cast<size_t>(i)]);
      CHECK(c.face.e_t_scale.cor[static_cast<size_t>(i)] == ref.e_t_scale.cor[static_cast<size_t>(i)]);
    }
    // The COR curves differ only by the club's face COR: the same slope in speed.
    const double slope = (c.face.e.at(30.0) - c.face.e.at(45.0)) / 15.0;
    CHECK(slope == Approx((ref.e.at(30.0) - ref.e.at(45.0)) / 15.0).epsilon(1e-9));
  }
}

TEST_CASE("spin rises and ball speed falls through the bag", "[delivery][calibration]") {
  // The TrackMan table's trend for the whole bag, with each row's speed and attack angle.
  const EquipmentCatalog& eq = test::assets().equipment();
  struct Row { const char* club; double mph, attack; };
  const Row rows[] = {{"driver", 113, -1.3}, {"3-wood", 107, -2.9}, {"5-wood", 103, -3.3}, {"hybrid", 100, -3.3},
                      {"3-iron", 98, -3.1}, {"4-iron", 96, -3.4}, {"5-iron", 94, -3.7}, {"6-iron", 92, -4.1},
                      {"7-iron", 90, -4.3}, {"8-iron", 87, -4.5}, {"9-iron", 85, -4.7}, {"pw", 83, -5.0}};
  double last_spin = 0, last_speed = 1e9;
  for (const Row& r : rows) {
    GolfSwing s;
    s.club_speed = mph_to_mps(r.mph);
    s.attack_angle = deg_to_rad(r.attack);
    const ClubSpec& c = eq.club(r.club);
    const LaunchMetrics m = measure_launch(deliver_golf(eq.ball("tour"), c, s, c.face).launch);
    INFO(r.club);
    CHECK(m.spin.total > last_spin);
    CHECK(m.ball_speed < last_speed);
    last_spin = m.spin.total;
    last_speed = m.ball_speed;
  }
}
