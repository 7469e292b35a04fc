// The fielding model (batting.hpp field_ball) and its throws (throwing.hpp): throws pay for
// drag and their arc; catches, grounders, and balls off the wall come out as a scorer
// would call them.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdio>

#include "game/rules/run_shot.hpp"
#include "game/modes/baseball/batting.hpp"
#include "game/modes/baseball/throwing.hpp"
#include "physics/error.hpp"
#include "physics/flight.hpp"
#include "physics/ground.hpp"
#include "physics/units.hpp"
#include "support/test_assets.hpp"

using namespace sweetspot;

namespace {
const AeroModel& aero() { return test::assets().aero(test::assets().sport("baseball").default_aero); }

// A batted ball on the ballpark from Statcast-style launch numbers.
BattedOutcome outcome(double ev_mph, double la_deg, double spray_deg, double spin_rpm, std::string* who) {
  const ResolvedShot r = resolve(test::launch_spec("baseball", ev_mph, la_deg, spin_rpm, spray_deg), test::assets());
  const ShotResult shot = run_shot(r, "test", {true, true});
  return field_ball(shot, *r.aero, r.spec.environment, who);
}

// A hand-made path's summary: lands at `land` after `hang` s, rests at `rest` after `end` s.
void summarise(ShotTrajectory& t, double hang, double end, const Vec3& land, const Vec3& rest) {
  t.summary.hang_time_s = hang;
  t.summary.total_time_s = end;
  t.summary.landing_position = land;
  t.summary.rest_position = rest;
  t.summary.carry_m = std::hypot(land.x(), land.z());
  t.summary.total_m = std::hypot(rest.x(), rest.z());
}
}  // namespace

TEST_CASE("a throw through the air takes longer than its distance at release speed", "[baseball][fielding]") {
  // An 86 mph arm (Statcast's average left fielder) over 80 m, the wall to second base: drag
  // takes ~20 % of the speed over the way and the throw must climb to carry that far.
  const double arm = mph_to_mps(86.0);
  const Throw t = throw_to(aero(), Environment{}, arm, 80.0, 0.6);
  INFO("80 m: " << t.time << " s at " << rad_to_deg(t.elevation) << " deg");
  CHECK(t.time > 1.2 * 80.0 / arm);
  CHECK(t.time > 2.5);  // ~2.8 s
  CHECK(t.time < 3.1);
  CHECK(t.elevation > deg_to_rad(5.0));
  CHECK(t.elevation < deg_to_rad(25.0));

  // The same throw flown again carries 80 m, released 1.8 m up, caught 1.0 m up.
  const ShotModel m = make_shot_model(baseball_properties(), aero(), Environment{}, nullptr);
  const LaunchState l = launch_from_metrics(arm, t.elevation, 0.0, rpm_to_radps(2283.0 / 94.19 * 86.0), 0.0,
                                            Vec3(0.0, baseball_properties().radius + 0.8, 0.0));
  ShotState s = start_state(l);
  while (!s.ended && step(m, s).kind != ShotEventKind::Landing) {
  }
  CHECK(std::hypot(s.position().x(), s.position().z()) == Approx(80.0).margin(0.02));
  CHECK(s.t == Approx(t.time).margin(1e-9));

  // Longer takes longer, across the switch to a relay too; a stronger arm is quicker; a
  // short toss is a line.
  double last = 0.0;
  for (double d = 5.0; d <= 130.0; d += 5.0) {
    const double time = throw_to(aero(), Environment{}, arm, d, 0.6).time;
    INFO(d << " m: " << time << " s");
    CHECK(time > last);
    last = time;
  }
  CHECK(throw_to(aero(), Environment{}, mph_to_mps(95.0), 80.0, 0.6).time < t.time);
  CHECK(throw_to(aero(), Environment{}, arm, 3.0, 0.6).time == Approx(3.0 / arm));
  // Past the arm's reach in the air (~105 m) a cutoff man relays it: two direct throws of
  // half the distance and the relay's transfer.
  const Throw half = throw_to(aero(), Environment{}, arm, 60.0, 0.6);
  CHECK(half.elevation > 0.0);  // 60 m is thrown on a rising line, not relayed again
  CHECK(throw_to(aero(), Environment{}, arm, 120.0, 0.6).time == Approx(2.0 * half.time + 0.6));
  // Nothing outside the stated ranges is thrown.
  CHECK_THROWS_AS(throw_to(aero(), Environment{}, 0.0, 50.0, 0.6), InputError);
  CHECK_THROWS_AS(throw_to(aero(), Environment{}, arm, std::nan(""), 0.6), InputError);
  CHECK_THROWS_AS(throw_to(aero(), Environment{}, arm, 1e300, 0.6), InputError);
}

TEST_CASE("fielding: fly balls in reach are caught, grounders at an infielder are outs, the gaps go for extra bases",
          "[baseball][fielding]") {
  std::string who;
  // A routine fly to centre (90 mph, 30°: ~300 ft, 4.5 s in the air) falls to the centre fielder.
  CHECK(outcome(90.0, 30.0, 0.0, 2000.0, &who) == BattedOutcome::Out);
  CHECK(who == "CF");
  // A 95 mph grounder (-5°) straight at the shortstop is thrown out at first.
  CHECK(outcome(95.0, -5.0, -12.0, 1500.0, &who) == BattedOutcome::Out);
  CHECK(who == "SS");
  // A soft line drive (80 mph, 12°) dropping in front of the centre fielder is a single.
  CHECK(outcome(80.0, 12.0, 0.0, 1500.0, &who) == BattedOutcome::Single);
  CHECK(who == "CF");
  // A 100 mph liner at 16° up the right-centre gap (~360 ft) lands between the fielders and
  // runs on to the wall: at least a double (a throw crossing at a fixed 90 % of its release
  // speed would make it a single, and no ball in play a double).
  const BattedOutcome gap = outcome(100.0, 16.0, 16.0, 2000.0, &who);
  INFO("gap: " << to_string(gap) << " fielded by " << who);
  CHECK((gap == BattedOutcome::Double || gap == BattedOutcome::Triple));
}

TEST_CASE("fly balls that reach the wall: doubles and triples, a few caught at the track; none rests in the infield",
          "[baseball][fielding][wall]") {
  // Drives that carry to the fence without clearing it, across the field: 96-112 mph at 14-30°
  // with a home-run hitter's 2500 rpm of backspin (Statcast's typical for those launches).
  int wall = 0, extra = 0, singles = 0, caught = 0, in_infield = 0;
  double nearest_rest = 1e9;
  for (double ev = 96.0; ev <= 112.0; ev += 2.0)
    for (double la = 14.0; la <= 30.0; la += 2.0)
      for (double spray = -40.0; spray <= 40.0; spray += 10.0) {
        const ResolvedShot r = resolve(test::launch_spec("baseball", ev, la, 2500.0, spray), test::assets());
        const ShotResult shot = run_shot(r, "test", {true, true});
        if (shot.end == ShotEnd::HomeRun || shot.trajectory.summary.landing_position.y() < 0.3) continue;  // not off the wall
        ++wall;
        const Vec3& rest = shot.trajectory.summary.rest_position;
        nearest_rest = std::min(nearest_rest, std::hypot(rest.x(), rest.z()));
        if (std::hypot(rest.x(), rest.z()) < 45.0) ++in_infield;  // the infield skin: 95 ft past the rubber
        const FieldingPlay p = field_play(shot, *r.aero, r.spec.environment, league_defense(), false, 8.23, nullptr);
        if (p.outcome == BattedOutcome::Double || p.outcome == BattedOutcome::Triple) ++extra;
        if (p.outcome == BattedOutcome::Single) ++singles;
        if (p.outcome == BattedOutcome::Out) ++caught;
      }
  INFO(wall << " off the wall: " << extra << " doubles or triples, " << singles << " singles, " << caught
            << " caught; nearest rest " << nearest_rest << " m from home");
  REQUIRE(wall >= 30);
  CHECK(in_infield == 0);
  CHECK(nearest_rest > 70.0);
  // A ball off the wall is a double for an average runner unless it caroms to a fielder.
  CHECK(extra >= 0.7 * wall);
  CHECK(singles <= 0.25 * wall);
  // Above a leaping fielder's glove it cannot be caught; at the track, lower, sometimes it is.
  CHECK(caught <= 0.2 * wall);
}

// An infielder throws on the run toward his target; running away from it he must stop first,
// across it half as much; time to spare he spends slowing down.
TEST_CASE("plant_time: the part of his run he must check before he throws", "[baseball][fielding]") {
  const FielderAbility f = league_defense().ability[4];  // the shortstop: 5 m/s²
  const Vec3 toward(0.0, 0.0, 1.0), away(0.0, 0.0, -1.0), across(1.0, 0.0, 0.0);
  CHECK(plant_time(f, 6.0, 0.0, toward, toward) == Approx(0.0).margin(1e-12));
  CHECK(plant_time(f, 6.0, 0.0, away, toward) == Approx(6.0 / f.accel));
  CHECK(plant_time(f, 6.0, 0.0, across, toward) == Approx(0.5 * 6.0 / f.accel));
  CHECK(plant_time(f, 6.0, 0.4, away, toward) == Approx((6.0 - 0.4 * f.accel) / f.accel));
  CHECK(plant_time(f, 6.0, 2.0, away, toward) == Approx(0.0).margin(1e-12));  // set before the ball came
  // His speed when he gets there: from rest at his acceleration, capped at his sprint.
  CHECK(run_speed(f, f.reach + 2.5) == Approx(std::sqrt(2.0 * f.accel * 2.5)));
  CHECK(run_speed(f, 100.0) == Approx(f.sprint));
}

// A grounder the shortstop must range far to his right for: he gets there only on the run
// away from first (or with a dive) and the long throw loses to the batter. The same ball at
// him is a routine out.
TEST_CASE("fielding: a grounder deep in the hole is an infield hit; the same ball at him an out", "[baseball][fielding]") {
  std::string who;
  CHECK(outcome(85.0, -4.0, -14.0, 1500.0, &who) == BattedOutcome::Out);
  CHECK(who == "SS");
  const BattedOutcome hole = outcome(85.0, -4.0, -27.0, 1500.0, &who);
  INFO("in the hole: " << to_string(hole) << " fielded by " << who);
  CHECK(hole == BattedOutcome::Single);
  CHECK((who == "SS" || who == "3B"));
}

// Fair or foul before the bases (Rule definitions, "fair ball"): a chopper that lands in
// front of the plate over fair ground and would roll across the first-base line to stop foul
// is fair once a fielder touches it over fair ground, foul only if it rolls foul untouched.
TEST_CASE("a chopper a fielder reaches over fair ground is fair, though it would have rolled foul", "[baseball][fielding]") {
  ShotResult shot;
  shot.end = ShotEnd::Rest;
  ShotTrajectory& t = shot.trajectory;
  const Vec3 bat(0.0, 0.9, 0.0), land(3.0, 0.037, 0.5), rest(14.0, 0.037, 17.0);  // rest: past the line (z > x)
  const double hang = 0.5, end = 8.0;  // s: a slow roller
  for (double at = 0.0; at <= end + 1e-9; at += 0.02) {
    TrajectorySample q;
    q.t = at;
    if (at < hang) {
      q.position = bat + (land - bat) * (at / hang);
      q.phase = Phase::Flight;
    } else {
      const double u = (at - hang) / (end - hang);
      q.position = land + (rest - land) * (u * (2.0 - u));  // slowing to a stop
      q.phase = Phase::Roll;
    }
    t.samples.push_back(q);
  }
  summarise(t, hang, end, land, rest);
  REQUIRE(rest.z() > rest.x());                         // it stops over foul ground
  REQUIRE(std::hypot(rest.x(), rest.z()) < 27.43);      // short of the bases
  const Defense defense = league_defense();
  CHECK_FALSE(is_fair_ball(shot));              // untouched: foul
  CHECK(is_fair_ball(shot, &defense, false));   // the pitcher, catcher or first baseman gets to it first
  const FieldingPlay p = field_play(shot, aero(), Environment{}, defense, false, 8.23, nullptr);
  CHECK_FALSE(p.foul);
  CHECK(p.outcome != BattedOutcome::Foul);
  REQUIRE(p.fielder >= 0);
  CHECK(p.fielded_at.z() < p.fielded_at.x());  // where he had it: fair ground
}

// The cage draws the batted ball as the play went: a catch ends its path in the glove, so a
// fly caught at the track does not go on to bounce off the wall behind the fielder.
TEST_CASE("as_played: a caught fly ends in the glove, a fielded ball where he picks it up, a home run goes on", "[baseball][fielding]") {
  int caught = 0, hits = 0;
  for (double ev = 90.0; ev <= 104.0; ev += 2.0)
    for (double spray = -30.0; spray <= 30.0; spray += 15.0) {
      const ResolvedShot r = resolve(test::launch_spec("baseball", ev, 30.0, 2500.0, spray), test::assets());
      const ShotResult shot = run_shot(r, "test", {true, true});
      const FieldingPlay p = field_play(shot, *r.aero, r.spec.environment, league_defense(), false, 8.23, nullptr);
      const ShotTrajectory t = as_played(shot.trajectory, p);
      if (p.caught) {
        ++caught;
        CHECK(t.samples.back().t == Approx(p.fielded_time));
        CHECK((t.samples.back().position - p.fielded_at).norm() < 1e-12);
        CHECK(t.samples.back().t < shot.trajectory.samples.back().t);
        for (const TrajectorySample& s : t.samples) CHECK(s.t <= p.fielded_time);
        // The ball was in the air until he had it: no bounce before the catch.
        for (std::size_t i = 0; i + 1 < t.samples.size(); ++i) CHECK(t.samples[i].phase == Phase::Flight);
      } else {
        ++hits;
        // A fair hit a fielder picks up ends there (not a ground-rule double or one already at rest).
        if (p.fielder >= 0 && !p.foul && p.fielded_time < shot.trajectory.summary.total_time_s) {
          CHECK((t.samples.back().position - p.fielded_at).norm() < 1e-12);
          CHECK(t.samples.back().t == Approx(p.fielded_time));
        } else {
          CHECK(t.samples.size() == shot.trajectory.samples.size());
        }
      }
    }
  CHECK(caught > 0);
  CHECK(hits > 0);
  // A hard grounder the shortstop fields ends in his glove, not rolling on to the wall.
  const ResolvedShot r = resolve(test::launch_spec("baseball", 91.0, -13.0, 1500.0, -10.0), test::assets());
  const ShotResult shot = run_shot(r, "test", {true, true});
  const FieldingPlay p = field_play(shot, *r.aero, r.spec.environment, league_defense(), false, 8.23, nullptr);
  const ShotTrajectory t = as_played(shot.trajectory, p);
  INFO("fielded by " << p.fielder << " at " << p.fielded_at.transpose() << ", rolled on to " << shot.trajectory.summary.rest_position.transpose());
  REQUIRE(p.fielder >= 0);
  REQUIRE(p.fielder < 6);
  CHECK((t.samples.back().position - p.fielded_at).norm() < 1e-12);
  CHECK(t.summary.rest_position.norm() < shot.trajectory.summary.rest_position.norm() - 10.0);
  // A home run keeps its whole flight into the seats.
  const ResolvedShot hr = resolve(test::launch_spec("baseball", 110.0, 28.0, 2500.0, 0.0), test::assets());
  const ShotResult long_ball = run_shot(hr, "test", {true, true});
  const FieldingPlay gone = field_play(long_ball, *hr.aero, hr.spec.environment, league_defense(), false, 8.23, nullptr);
  CHECK(gone.outcome == BattedOutcome::HomeRun);
  CHECK(as_played(long_ball.trajectory, gone).samples.size() == long_ball.trajectory.samples.size());
}

TEST_CASE("as_played: a foul ground ball is dead where it is called, not after it rolls up the line", "[baseball][fielding]") {
  // A topped ball outside the third-base line (65 mph, -12 deg, 50 deg off the mound's line):
  // the physics rolls it on up the foul ground; the umpire calls it where it passes the bag,
  // or where a fielder touches it, and the play ends there (Rule 5.06(c)(5)).
  for (const double spray : {-50.0, 50.0, -60.0}) {
    const ResolvedShot r = resolve(test::launch_spec("baseball", 65.0, -12.0, 1500.0, spray), test::assets());
    const ShotResult shot = run_shot(r, "test", {true, true});
    const FieldingPlay p = field_play(shot, *r.aero, r.spec.environment, league_defense(), false, 8.23, nullptr);
    INFO("spray " << spray << ": rolled " << m_to_ft(shot.trajectory.summary.total_m) << " ft in " << shot.trajectory.summary.total_time_s
                  << " s; called at " << m_to_ft(std::hypot(p.called_at.x(), p.called_at.z())) << " ft, " << p.called_time << " s");
    REQUIRE(p.outcome == BattedOutcome::Foul);
    REQUIRE_FALSE(p.caught);
    REQUIRE(shot.trajectory.summary.total_m > ft_to_m(150.0));  // it rolls on a long way
    const ShotTrajectory t = as_played(shot.trajectory, p);
    CHECK(p.called_time > 0.0);
    CHECK(t.summary.total_time_s == Approx(p.called_time));
    CHECK(t.summary.total_time_s < shot.trajectory.summary.total_time_s - 1.0);
    CHECK((t.samples.back().position - p.called_at).norm() < 1e-12);
    // Called by the bag (90 ft) or before it, where a corner infielder touches it.
    CHECK(t.summary.total_m <= ft_to_m(100.0));
  }
}

TEST_CASE("a pop-up that drifts past the bases' distance in the air and lands short of them is judged where it settles",
          "[baseball][fielding]") {
  // Up to 29 m out over fair ground at its top, down at 23 m (31 deg, fair) short of the
  // bases, then off into the stands down the third-base side: foul (Rule definitions: a ball
  // short of the bases is fair or foul where it settles or is touched, not where it flew).
  // It used to be called by where its flight crossed the bases' distance: a ground-rule double.
  ShotResult shot;
  shot.end = ShotEnd::OutOfBounds;
  ShotTrajectory& t = shot.trajectory;
  const Vec3 bat(0.0, 0.9, 0.0), top(28.0, 30.0, -8.0), land(20.0, 0.037, -12.0), gone(2.0, 0.037, -22.0);
  const double apex = 3.0, hang = 5.8, end = 8.0;
  for (double at = 0.0; at <= end + 1e-9; at += 0.02) {
    TrajectorySample q;
    q.t = at;
    if (at < apex) q.position = bat + (top - bat) * (at / apex);
    else if (at < hang) q.position = top + (land - top) * ((at - apex) / (hang - apex));
    else q.position = land + (gone - land) * ((at - hang) / (end - hang));
    q.phase = at < hang ? Phase::Flight : Phase::Roll;
    t.samples.push_back(q);
  }
  summarise(t, hang, end, land, gone);
  CHECK_FALSE(is_fair_ball(shot));
  const FieldingPlay p = field_play(shot, aero(), Environment{}, league_defense(), false, 8.23, nullptr);
  CHECK(p.outcome != BattedOutcome::Double);
}

TEST_CASE("a ball past the catcher before he can react is a foul, never a foul out", "[baseball][fielding]") {
  // Straight back off the bat at 30 m/s, 1 m up: it passes the catcher's mitt (4 ft back)
  // 0.04 s after contact and reaches the backstop (15 m) at 0.5 s. A catcher's glove in a
  // foul tip's path makes a strike of it (Rule definitions: foul tip), never a caught foul
  // fly; it used to be "Foul out to C" about 2 % of the time.
  ShotResult shot;
  shot.end = ShotEnd::OutOfBounds;
  ShotTrajectory& t = shot.trajectory;
  for (int i = 0; i <= 250; ++i) {
    TrajectorySample q;
    q.t = 0.002 * i;
    q.position = Vec3(-30.0 * q.t, 1.0, 0.0);
    q.phase = Phase::Flight;
    t.samples.push_back(q);
  }
  t.summary.hang_time_s = t.summary.total_time_s = 0.5;
  t.summary.landing_position = t.summary.rest_position = t.samples.back().position;
  t.summary.carry_m = t.summary.total_m = 15.0;
  const FieldingPlay p = field_play(shot, aero(), Environment{}, league_defense(), false, 8.23, nullptr);
  CHECK(p.foul);
  CHECK(p.outcome == BattedOutcome::Foul);
  CHECK_FALSE(p.caught);
  CHECK(p.catch_probability < 1e-6);
}

TEST_CASE("a foul tip ends in the catcher's mitt, 4 ft behind the plate, not at the backstop", "[modes][baseball]") {
  // A ball going straight back from the plate at 30 m/s, 1 m up, sampled every millisecond
  // for 0.5 s (15 m: the backstop's distance).
  ShotTrajectory back;
  for (int i = 0; i <= 500; ++i) {
    TrajectorySample s;
    s.t = 0.001 * i;
    s.position = Vec3(-30.0 * s.t, 1.0, 0.0);
    back.samples.push_back(s);
  }
  back.summary.total_m = back.summary.carry_m = 15.0;
  back.summary.total_time_s = 0.5;
  const ShotTrajectory mitt = into_the_mitt(back);
  CHECK(mitt.summary.total_m == Approx(4.0 * 0.3048).margin(0.03));  // the catcher's spot (fielding.cpp kSpots)
  CHECK(mitt.summary.carry_m == mitt.summary.total_m);
  CHECK(mitt.summary.total_time_s == Approx(4.0 * 0.3048 / 30.0).margin(0.002));
  CHECK(mitt.samples.back().phase == Phase::Rest);
  CHECK(mitt.samples.back().position.y() == 1.0);  // caught where it flew, at the mitt's height
  // A ball that never got that far back is left as it was.
  back.samples.resize(20);
  CHECK(into_the_mitt(back).samples.size() == 20);
}
