// Calibration against the TrackMan PGA Tour averages (TrackMan 2004–2008 tour averages;
// DESIGN §4): the default equipment, each club's documented dynamic loft and strike, and the
// row's club speed and attack angle reproduce ball speed within 3 %, launch angle within
// 1.5° and spin within 15 % for all twelve rows. One physical model for every club: the same
// ball and ball–face contact law (the compliant impact, µ, friction model); only measured or
// documented per-club data (loft, mass, CG, inertia, face COR) and the delivery differ.
#include <catch2/catch.hpp>

#include <cmath>
#include <span>
#include <string>
#include <vector>

#include "game/content/equipment_file.hpp"
#include "game/tuning/trackman_averages.hpp"
#include "support/test_assets.hpp"
#include "physics/delivery.hpp"
#include "physics/flight.hpp"
#include "physics/units.hpp"

using namespace sweetspot;

namespace {
/// A TrackMan row with its delivery and its flight (game/tuning/trackman_averages.hpp).
struct TrackManRow {
  const char* club;
  double club_mph, attack_deg, ball_mph, launch_deg, spin_rpm, carry_yd, landing_deg;
};

std::vector<TrackManRow> joined(std::span<const TourSwing> swings, std::span<const TourFlight> flights) {
  std::vector<TrackManRow> rows;
  for (const TourSwing& s : swings) {
    const TourFlight& f = tour_flight(flights, s.club);
    rows.push_back({s.club, s.club_mph, s.attack_deg, f.ball_mph, f.launch_deg, f.spin_rpm, f.carry_yd, f.landing_deg});
  }
  return rows;
}

const std::vector<TrackManRow> kRows = joined(kPgaTourSwings, kPgaTourFlights);

GolfSwing row_swing(const TrackManRow& row) {
  GolfSwing s;
  s.club_speed = mph_to_mps(row.club_mph);
  s.attack_angle = deg_to_rad(row.attack_deg);
  return s;
}

/// The row's swing with the dynamic loft (bisected to 40 halvings) that launches at its angle.
GolfSwing swing_launching_at_row(const ClubSpec& club, const TrackManRow& row) {
  const BallSpec& ball = test::assets().equipment().ball("tour");
  GolfSwing s = row_swing(row);
  double lo = deg_to_rad(2.0), hi = deg_to_rad(70.0);
  for (int i = 0; i < 40; ++i) {
    s.dynamic_loft = 0.5 * (lo + hi);
    const double launch = measure_launch(deliver_golf(ball, club, s, club.face).launch).vertical_angle;
    (launch < deg_to_rad(row.launch_deg) ? lo : hi) = s.dynamic_loft;
  }
  s.dynamic_loft = 0.5 * (lo + hi);
  return s;
}
}  // namespace

TEST_CASE("tour deliveries reproduce the TrackMan PGA averages", "[delivery][calibration]") {
  const EquipmentCatalog& eq = test::assets().equipment();
  const BallSpec& ball = eq.ball("tour");
  for (const TrackManRow& row : kRows) {
    const ClubSpec& club = eq.club(row.club);
    const Delivery d = deliver_golf(ball, club, row_swing(row), club.face);
    const LaunchMetrics m = measure_launch(d.launch);
    INFO(row.club << ": ball " << mps_to_mph(m.ball_speed) << " mph (TrackMan " << row.ball_mph << "), launch "
                  << rad_to_deg(m.vertical_angle) << " deg (" << row.launch_deg << "), spin "
                  << radps_to_rpm(m.spin.total) << " rpm (" << row.spin_rpm << "), dynamic loft "
                  << rad_to_deg(club.dynamic_loft) << " deg, smash " << d.smash_factor);
    CHECK(d.compliant);
    CHECK(mps_to_mph(m.ball_speed) == Approx(row.ball_mph).epsilon(0.03));
    CHECK(rad_to_deg(m.vertical_angle) == Approx(row.launch_deg).margin(1.5));
    CHECK(radps_to_rpm(m.spin.total) == Approx(row.spin_rpm).epsilon(0.15));
    CHECK(std::abs(rad_to_deg(m.horizontal_angle)) < 0.5);
    CHECK(std::abs(rad_to_deg(m.spin.axis_rad)) < 3.0);
  }
}

TEST_CASE("tour deliveries carry and land like the TrackMan PGA averages", "[delivery][calibration][flight]") {
  // The calibration bands on flat ground, standard air: carry within 4 % and landing angle
  // within 3° of the row, the whole shot predicted from the club's delivery. The driver's
  // carry is the closest to its edge (−3.87 %, 264.4 yd: 0.4 yd inside): its ball leaves
  // 2.9 % slow, at this head's free-body smash ceiling for the USGA COR limit (docs/physics.md,
  // the delivery row).
  const EquipmentCatalog& eq = test::assets().equipment();
  const ShotModel model = test::golf_model();
  for (const TrackManRow& row : kRows) {
    const ClubSpec& club = eq.club(row.club);
    const ShotTrajectory t = simulate_shot(model, deliver_golf(eq.ball("tour"), club, row_swing(row), club.face).launch, false);
    const double carry_yd = t.summary.carry_m / 0.9144;
    INFO(row.club << ": carry " << carry_yd << " yd (TrackMan " << row.carry_yd << "), landing "
                  << t.summary.landing_angle_deg << " deg (" << row.landing_deg << ")");
    CHECK(t.summary.landing_angle_deg == Approx(row.landing_deg).margin(3.0));
    CHECK(carry_yd == Approx(row.carry_yd).epsilon(0.04));
  }
}

TEST_CASE("the contact law carries over to TrackMan's LPGA irons, rows it was never fitted to", "[delivery][calibration]") {
  // TrackMan LPGA Tour averages (the same 2004–2008 table as DESIGN §4's PGA rows): slower
  // clubs (70–80 mph) and shallower attacks. Only the delivered loft is solved again, from
  // each row's launch angle (LPGA players present other lofts); ball speed and spin are then
  // predicted with the PGA calibration's bands. The LPGA 5-wood (4501 rpm at 12.1°) spins 16 %
  // more than this model gives; the LPGA driver row depends on where they strike it.
  const EquipmentCatalog& eq = test::assets().equipment();
  const ShotModel model = test::golf_model();
  const std::vector<TrackManRow> lpga = joined(kLpgaTourIronSwings, kLpgaTourFlights);
  for (const TrackManRow& row : lpga) {
    const ClubSpec& club = eq.club(row.club);
    const GolfSwing s = swing_launching_at_row(club, row);
    const LaunchMetrics m = measure_launch(deliver_golf(eq.ball("tour"), club, s, club.face).launch);
    INFO("LPGA " << row.club << ": ball " << mps_to_mph(m.ball_speed) << " mph (TrackMan " << row.ball_mph << "), spin "
                 << radps_to_rpm(m.spin.total) << " rpm (" << row.spin_rpm << "), dynamic loft "
                 << rad_to_deg(s.dynamic_loft) << " deg");
    CHECK(mps_to_mph(m.ball_speed) == Approx(row.ball_mph).epsilon(0.03));
    CHECK(radps_to_rpm(m.spin.total) == Approx(row.spin_rpm).epsilon(0.15));
    // And it carries within the PGA bands' 4 % and lands within their 3° (the 4-iron carries
    // −3.2 %).
    const ShotTrajectory t = simulate_shot(model, deliver_golf(eq.ball("tour"), club, s, club.face).launch, false);
    INFO("carry " << t.summary.carry_m / 0.9144 << " yd (" << row.carry_yd << "), landing " << t.summary.landing_angle_deg
                  << " deg (" << row.landing_deg << ")");
    CHECK(t.summary.landing_angle_deg == Approx(row.landing_deg).margin(3.0));
    CHECK(t.summary.carry_m / 0.9144 == Approx(row.carry_yd).epsilon(0.04));
  }
}

TEST_CASE("each club's documented dynamic loft is the one that launches at its row's angle", "[delivery][calibration]") {
  // clubs.toml's dynamic lofts are fitted to launch angle only; solving again keeps the
  // data honest when the contact model changes (spin and ball speed are then predictions).
  const EquipmentCatalog& eq = test::assets().equipment();
  for (const TrackManRow& row : kRows) {
    const ClubSpec& club = eq.club(row.club);
    const double solved = swing_launching_at_row(club, row).dynamic_loft;
    INFO(row.club << ": documented " << rad_to_deg(club.dynamic_loft) << " deg, solved " << rad_to_deg(solved));
    CHECK(rad_to_deg(club.dynamic_loft) == Approx(rad_to_deg(solved)).margin(0.1));
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
    CHECK(c.face.model == ref.model);
    CHECK(c.shaft_tip_mass == eq.club("driver").shaft_tip_mass);
    // The COR curves differ only by the club's face COR: the same slope in speed.
    const double slope = (c.face.e.at(30.0) - c.face.e.at(45.0)) / 15.0;
    CHECK(slope == Approx((ref.e.at(30.0) - ref.e.at(45.0)) / 15.0).epsilon(1e-9));
  }
}

TEST_CASE("spin rises and ball speed falls through the bag", "[delivery][calibration]") {
  // The TrackMan table's trend for the whole bag, with each row's speed and attack angle.
  const EquipmentCatalog& eq = test::assets().equipment();
  double last_spin = 0, last_speed = 1e9;
  for (const TourSwing& r : kPgaTourSwings) {
    GolfSwing s;
    s.club_speed = mph_to_mps(r.club_mph);
    s.attack_angle = deg_to_rad(r.attack_deg);
    const ClubSpec& c = eq.club(r.club);
    const LaunchMetrics m = measure_launch(deliver_golf(eq.ball("tour"), c, s, c.face).launch);
    INFO(r.club);
    CHECK(m.spin.total > last_spin);
    CHECK(m.ball_speed < last_speed);
    last_spin = m.spin.total;
    last_speed = m.ball_speed;
  }
}
