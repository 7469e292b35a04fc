// The golf game (DESIGN §9): the course file, the stroke loop's penalties and scoring, the
// putt that lips out too fast and drops slower, the lie changing the strike, bad files.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <unistd.h>

#include "game/content/course_file.hpp"
#include "game/content/swings_file.hpp"
#include "game/modes/golf/bot.hpp"
#include "game/modes/golf/round.hpp"
#include "physics/error.hpp"
#include "support/test_assets.hpp"

using namespace sweetspot;
using Catch::Matchers::Contains;
namespace fs = std::filesystem;

namespace {

// The links with only hole `n` (1-based), its tee moved to `tee` (x, z) when given.
Course one_hole(int n, std::optional<std::pair<double, double>> tee = std::nullopt) {
  Course c = test::links();
  c.holes = {test::links().holes[static_cast<std::size_t>(n - 1)]};
  c.holes[0].number = 1;
  if (tee) {
    SurfaceContact hit;
    const WorldAsset& w = *c.holes[0].world;
    REQUIRE(ground_under(*w.world, tee->first, tee->second, 400.0, 420.0, &hit));
    c.holes[0].tee = hit.point;
  }
  return c;
}

StrokeInput stroke(const char* club, double power, double accuracy_ms = 0.0, double aim = 0.0) {
  StrokeInput in;
  in.club = club;
  in.meter.power = power;
  in.meter.accuracy_ms = accuracy_ms;
  in.aim = aim;
  return in;
}

struct TempFile {
  fs::path path;
  explicit TempFile(const std::string& name, const std::string& text)
      : path(fs::temp_directory_path() / ("sweetspot_" + std::to_string(::getpid()) + "_" + name)) {
    std::ofstream(path) << text;
  }
  ~TempFile() { fs::remove(path); }
};

}  // namespace

TEST_CASE("the Sweetspot Links: a par 3, a par 4 and a par 5 with tees and cups", "[golf][course]") {
  const Course& c = test::links();
  REQUIRE(c.holes.size() == 3);
  CHECK(c.holes[0].par == 3);
  CHECK(c.holes[1].par == 4);
  CHECK(c.holes[2].par == 5);
  CHECK(c.par() == 12);
  for (const CourseHole& h : c.holes) {
    INFO(h.world_name);
    CHECK(h.length() > 100.0);
    SurfaceContact hit;
    REQUIRE(ground_under(*h.world->world, h.pin.x(), h.pin.z(), 400.0, 420.0, &hit));
    CHECK(h.world->world->material(hit.material).kind == SurfaceKind::Green);
    REQUIRE(ground_under(*h.world->world, h.tee.x(), h.tee.z(), 400.0, 420.0, &hit));
    CHECK(h.world->world->material(hit.material).kind == SurfaceKind::Tee);
  }
  // The par lengths of the USGA's guidance: a par 3 up to ~260 yd, par 4 ~240-490, par 5 ~450-710.
  CHECK(c.holes[0].length() < 238.0);
  CHECK(c.holes[1].length() > 219.0);
  CHECK(c.holes[2].length() > 411.0);
}

TEST_CASE("out of bounds costs stroke and distance; water a stroke and a drop", "[golf][round][rules]") {
  // Hole 3: out of bounds all along the right. A driver 150 ms late opens the face ~12°.
  GolfRound ob(test::assets(), one_hole(3), golfer_skill("tour"));
  const StrokeRecord first = ob.play(stroke("driver", 1.0, 150.0, 0.25));
  CHECK(first.end == StrokeEnd::OutOfBounds);
  CHECK(first.penalty == 1);
  CHECK(ob.card()[0].strokes == 2);  // the shot and the penalty
  CHECK(ob.teed());                  // played again from the tee
  CHECK((ob.ball() - test::links().holes[2].tee).norm() < 1e-9);

  // Hole 1: the pond fills the approach short of the green; a soft 7-iron finds it.
  GolfRound water(test::assets(), one_hole(1), golfer_skill("tour"));
  const StrokeRecord wet = water.play(stroke("7-iron", 0.72));
  REQUIRE(wet.end == StrokeEnd::Water);
  CHECK(wet.penalty == 1);
  CHECK(water.card()[0].strokes == 2);
  CHECK(water.card()[0].penalties == 1);
  // The drop: out of the water, back on the line toward where it was struck.
  CHECK(water.lie() != "water");
  CHECK(water.ball().x() < wet.rest.x());
  CHECK(!water.teed());
}

TEST_CASE("a putt lips out at too high a speed and drops at a lower one", "[golf][round][putting]") {
  // Hole 1's green, 3 m short of the cup on its line.
  const CourseHole& h = test::links().holes[0];
  const auto tee = std::make_pair(h.pin.x() - 3.0, h.pin.z());
  GolfRound probe(test::assets(), one_hole(1, tee), golfer_skill("tour"));
  REQUIRE(probe.lie() == "green");
  // The bot's caddie finds the line and speed that hole it; then the same line twice as hard.
  GolfBot caddie(test::assets(), golfer_skill("tour"), 1);
  const StrokeInput good = caddie.intend(probe);
  CHECK(probe.simulate(good).end == ShotEnd::Holed);
  // Twice as hard, on the line that now runs over the middle of the cup (a faster putt
  // breaks less): it crosses the hole and does not drop.
  const auto closest_approach = [&](const ShotResult& r) {
    double closest = 1e9;
    const auto& sm = r.trajectory.samples;
    for (std::size_t k = 1; k < sm.size(); ++k) {
      const Vec3 a(sm[k - 1].position.x() - h.pin.x(), 0, sm[k - 1].position.z() - h.pin.z());
      const Vec3 d(sm[k].position.x() - sm[k - 1].position.x(), 0, sm[k].position.z() - sm[k - 1].position.z());
      const double t = d.squaredNorm() > 0 ? std::clamp(-a.dot(d) / d.squaredNorm(), 0.0, 1.0) : 0.0;
      closest = std::min(closest, (a + t * d).norm());
    }
    return closest;
  };
  StrokeInput hard = good;
  hard.meter.power = std::min(1.1, good.meter.power * 2.0);
  double best = 1e9, best_aim = 0.0;
  for (int i = -40; i <= 40; ++i) {
    hard.aim = good.aim + 0.0025 * i;
    const double c = closest_approach(probe.simulate(hard, true));
    if (c < best) {
      best = c;
      best_aim = hard.aim;
    }
  }
  hard.aim = best_aim;
  const ShotResult fast = probe.simulate(hard, true);
  CHECK(best < 0.02);
  CHECK(fast.end != ShotEnd::Holed);
  // Played, the good one counts one putt and ends the hole.
  GolfRound play(test::assets(), one_hole(1, tee), golfer_skill("tour"));
  const StrokeRecord r = play.play(good);
  CHECK(r.end == StrokeEnd::Holed);
  CHECK(play.card()[0].putts == 1);
  CHECK(play.card()[0].holed);
  CHECK(play.finished());
}

TEST_CASE("a stroke aimed off the pin is recorded on the side it was aimed", "[golf][round]") {
  // The same putt from 3 m short of hole 1's cup aimed 10 deg right, then 10 deg left: it
  // stops on that side of the line from the ball to the cup (the HUD's "short, right"), and
  // its side and its pace together make up its distance from the cup.
  const CourseHole& h = test::links().holes[0];
  const auto tee = std::make_pair(h.pin.x() - 3.0, h.pin.z());
  GolfBot caddie(test::assets(), golfer_skill("tour"), 1);
  for (const double aim : {deg_to_rad(10.0), deg_to_rad(-10.0)}) {
    GolfRound round(test::assets(), one_hole(1, tee), golfer_skill("tour"));
    StrokeInput in = caddie.intend(round);
    in.aim = aim;
    const StrokeRecord r = round.play(in);
    REQUIRE(r.end == StrokeEnd::Rest);
    INFO("aim " << rad_to_deg(aim) << " deg: " << r.to_pin_m << " m from the cup, past " << r.past_m << ", right " << r.right_m);
    CHECK(r.right_m * aim > 0.0);
    CHECK(std::abs(r.right_m) > 0.3);
    CHECK(std::hypot(r.past_m, r.right_m) == Approx(r.to_pin_m).epsilon(1e-6));
  }
}

TEST_CASE("a putt left out is recorded as so far past the cup or short of it, along its line", "[golf][round][putting]") {
  // Hole 1's green, 3 m short of the cup on its line: the caddie's putt holes; half its pace
  // stops short, twice it runs past; the shortfall and the overshoot are measured along the
  // line from the ball to the cup, so they never exceed the distance left.
  const CourseHole& h = test::links().holes[0];
  const auto tee = std::make_pair(h.pin.x() - 3.0, h.pin.z());
  GolfBot caddie(test::assets(), golfer_skill("tour"), 1);
  for (const double pace : {0.5, 2.0}) {
    GolfRound round(test::assets(), one_hole(1, tee), golfer_skill("tour"));
    StrokeInput in = caddie.intend(round);
    in.meter.power = std::min(1.1, in.meter.power * pace);
    const StrokeRecord r = round.play(in);
    REQUIRE(r.end == StrokeEnd::Rest);
    INFO("pace x" << pace << ": " << r.to_pin_m << " m from the cup, past " << r.past_m);
    CHECK(std::abs(r.past_m) <= r.to_pin_m + 1e-9);
    CHECK(std::abs(r.past_m) > 0.5 * r.to_pin_m);  // on its line: the pace's error, not the line's
    if (pace < 1.0) CHECK(r.past_m < 0.0);
    else CHECK(r.past_m > 0.0);
  }
}

TEST_CASE("the lie is the surface under the ball and changes the strike", "[golf][round][lie]") {
  const CourseHole& h = test::links().holes[1];
  GolfRound fairway(test::assets(), one_hole(2, std::make_pair(150.0, -2.0)), golfer_skill("tour"));
  GolfRound rough(test::assets(), one_hole(2, std::make_pair(150.0, 40.0)), golfer_skill("tour"));
  REQUIRE(fairway.lie() == "fairway");
  REQUIRE(rough.lie() == "rough");
  (void)h;
  const ShotResult a = fairway.simulate(stroke("8-iron", 1.0));
  const ShotResult b = rough.simulate(stroke("8-iron", 1.0));
  CHECK(a.lie == "fairway");
  CHECK(b.lie == "rough");
  // The flyer: grass on the face, less spin and a higher launch (materials.toml's rough).
  CHECK(b.launch.spin.total < 0.9 * a.launch.spin.total);
  CHECK(b.launch.vertical_angle > a.launch.vertical_angle);
}

TEST_CASE("a hole ends at the 10-stroke pick-up", "[golf][round][rules]") {
  GolfRound r(test::assets(), one_hole(3), golfer_skill("beginner"));
  for (int i = 0; i < 12 && !r.finished(); ++i) r.play(stroke("driver", 1.0, 150.0, 0.25));  // OB every time
  REQUIRE(r.finished());
  CHECK(r.card()[0].strokes == GolfRound::kPickUp);
  CHECK_FALSE(r.card()[0].holed);
}

TEST_CASE("a bot round is the same bit for bit for the same seed, and holes out", "[golf][bot]") {
  auto play = [](std::uint64_t seed) {
    GolfRound round(test::assets(), test::links(), golfer_skill("tour"));
    GolfBot bot(test::assets(), golfer_skill("tour"), seed);
    std::vector<Vec3> rests;
    while (!round.finished()) rests.push_back(round.play(bot.plan(round)).rest);
    return std::make_pair(rests, round.card());
  };
  const auto a = play(7), b = play(7);
  REQUIRE(a.first.size() == b.first.size());
  for (std::size_t i = 0; i < a.first.size(); ++i) CHECK(a.first[i] == b.first[i]);
  for (const HoleCard& h : a.second) CHECK(h.holed);
}

TEST_CASE("bad course and swings files name file:line and the range", "[golf][input]") {
  TempFile no_tee("no_tee.toml", "name = \"x\"\n[[hole]]\nnumber = 1\npar = 4\nworld = \"links_2\"\n");
  CHECK_THROWS_WITH(load_course(test::assets(), no_tee.path.string()), Contains(":2") && Contains("tee"));
  TempFile bad_par("bad_par.toml", "name = \"x\"\n[[hole]]\nnumber = 1\npar = 9\nworld = \"links_2\"\ntee = [\"0m\", \"0m\"]\n");
  CHECK_THROWS_WITH(load_course(test::assets(), bad_par.path.string()), Contains(":4") && Contains("par") && Contains("[3, 6]"));
  // A world that has no cup, and a hole that names none.
  const fs::path worlds = test::assets().root() / "worlds";
  TempFile world("nopin.toml", "name = \"nopin\"\nsport = \"golf\"\nmesh = \"" + (worlds / "links_2.obj").string() +
                                   "\"\norigin = [\"0m\", \"0m\", \"0m\"]\nbounds_min = [\"-25m\", \"-10m\", \"-65m\"]\n"
                                   "bounds_max = [\"410m\", \"400m\", \"55m\"]\n");
  TempFile no_pin("no_pin.toml", "name = \"x\"\n[[hole]]\nnumber = 1\npar = 4\nworld = \"" + world.path.string() +
                                     "\"\ntee = [\"0m\", \"0m\"]\n");
  CHECK_THROWS_WITH(load_course(test::assets(), no_pin.path.string()), Contains(":2") && Contains("missing pin"));
  TempFile swings("swings.toml", "[[stroke]]\npower = \"95%\"\n[[stroke]]\nclub = \"driver\"\npower = \"140%\"\n");
  CHECK_THROWS_WITH(load_swings(swings.path), Contains(":5") && Contains("power = 140 %") && Contains("(0, 110] %"));
}

// A dogleg's corner well inside a long club's carry, the green out of reach: a golfer plays a
// long club past the corner along the next leg, not a wedge to the corner. On the National's
// 12th (a par 5 whose line bends ~100 m past an amateur's drive) the amateur bot used to lay
// up 100 m with a 9-iron from 320 m out.
TEST_CASE("out of reach with a bend close ahead, a bot plays past the bend, not a wedge to it", "[golf][bot]") {
  const GolferSkill& amateur = golfer_skill("amateur");
  Course course = load_course(test::assets(), "national");
  course.holes = {course.holes[11]};
  REQUIRE(course.holes[0].par == 5);
  REQUIRE_FALSE(course.holes[0].bends.empty());
  int checked = 0;
  for (const double aim : {-0.06, -0.03, 0.0, 0.03, 0.06}) {
    GolfRound round(test::assets(), course, amateur);
    StrokeInput drive;
    drive.club = "driver";
    drive.aim = aim;
    round.play(drive);
    const std::optional<Vec3> bend = round.next_bend();
    if (round.finished() || round.lie() == "sand" || !bend) continue;
    const GolfBot bot(test::assets(), amateur, 1);
    const double to_bend = std::hypot(bend->x() - round.ball().x(), bend->z() - round.ball().z());
    const double longest = bot.stock()[1].carry;  // the 3-wood: no driver off the deck
    if (round.to_pin() <= bot.stock()[1].total || longest - to_bend < 30.0) continue;
    const StrokeInput in = bot.intend(round);
    const auto stock = std::find_if(bot.stock().begin(), bot.stock().end(), [&](const GolfBot::Stock& s) { return s.club == in.club; });
    REQUIRE(stock != bot.stock().end());
    INFO("aim " << aim << ": " << round.to_pin() << " m to go from the " << round.lie() << ", the bend " << to_bend
                << " m ahead: " << in.club << " (" << stock->carry << " m)");
    CHECK(stock->carry > to_bend + 30.0);
    ++checked;
  }
  CHECK(checked >= 2);
}

TEST_CASE("into a wind that holds the wedge's full swing short of the cup, the caddie takes more club", "[golf][bot]") {
  // 97 % of the lob wedge's calm carry from the cup: in still air the wedge; into a 9 m/s wind
  // its full swing comes down short, in the water before this green (a play-test: "lob wedge,
  // stock carry 78 yd; from here 66 yd" chosen for 77 yd), and a longer club gets there.
  const GolferSkill& scratch = golfer_skill("scratch");
  const GolfBot bot(test::assets(), scratch, 1);
  const GolfBot::Stock& wedge = bot.stock().back();
  const Course plain = one_hole(1);
  const CourseHole& h0 = plain.holes[0];
  Vec3 back = h0.tee - h0.pin;
  back.y() = 0.0;
  back.normalize();
  const Vec3 spot = h0.pin + 0.97 * wedge.carry * back;
  for (const double wind : {0.0, 9.0}) {
    const Course course = one_hole(1, std::pair{spot.x(), spot.z()});
    HoleWind w;
    w.speed = wind;
    w.toward = std::atan2(back.z(), back.x());  // toward the player
    GolfRound round(test::assets(), course, scratch, {w});
    const StrokeInput in = bot.intend(round);
    const Vec3 rest = round.simulate(in).trajectory.summary.rest_position;
    const double left = std::hypot(rest.x() - h0.pin.x(), rest.z() - h0.pin.z());
    INFO("wind " << wind << " m/s, " << round.to_pin() << " m to go: " << in.club << " at " << in.meter.power << ", stops " << left
                 << " m from the cup");
    // In still air the wedge, or the next club up swung smooth where the wedge's full swing
    // would stop a metre or more short (the meter would call it an overswing); into the wind
    // never the wedge.
    if (wind > 0.0) CHECK(in.club != wedge.club);
    else CHECK((in.club == wedge.club || in.club == bot.stock()[bot.stock().size() - 2].club));
    CHECK(in.meter.power <= 1.0);
    CHECK(left < 8.0);
  }
}

// Behind a tree a golfer takes a way out: a line beside it, or a club that flies under or over
// it. On the National's 9th, from the left rough ~225 m out, a tree stands ~15 m ahead on the
// line to the flag; the amateur bot used to hit its 3-wood into it (carry 14 m) every time.
TEST_CASE("behind a tree, a bot plays a way out that clears it, not a club into its branches", "[golf][bot]") {
  const GolferSkill& amateur = golfer_skill("amateur");
  Course course = load_course(test::assets(), "national");
  course.holes = {course.holes[8]};
  SurfaceContact hit;
  REQUIRE(ground_under(*course.holes[0].world->world, -307.4, -473.5, 400.0, 420.0, &hit));
  course.holes[0].tee = hit.point;
  const GolfRound round(test::assets(), course, amateur);
  const GolfBot bot(test::assets(), amateur, 1);
  // Straight at the flag every long club strikes the tree.
  for (const char* club : {"3-wood", "5-wood", "hybrid"}) {
    StrokeInput straight;
    straight.club = club;
    INFO(club << " at the flag");
    REQUIRE(round.first_touch_in_a_tree(round.simulate(straight).trajectory.summary));
  }
  const StrokeInput in = bot.intend(round);
  const ShotResult r = round.simulate(in);
  const Vec3& rest = r.trajectory.summary.rest_position;
  const double to_cup = std::hypot(course.holes[0].pin.x() - rest.x(), course.holes[0].pin.z() - rest.z());
  INFO(in.club << " aimed " << in.aim << " rad: carry " << r.trajectory.summary.carry_m << " m, " << to_cup << " m left on the "
               << round.surface_at(rest));
  CHECK_FALSE(round.first_touch_in_a_tree(r.trajectory.summary));
  CHECK(r.end == ShotEnd::Rest);
  CHECK(to_cup < round.to_pin() - 60.0);  // a real advance toward the cup, not a chip sideways
  CHECK(round.surface_at(rest) != "sand");
}

// A chip over rough to a cup 14 m away (the National's 7th, the cup cut near the green's edge
// by the day's pins): a ball landing in the rough stops dead, one a little firmer runs on,
// and the bot's aim-and-power corrections swung about the cup and ended 6 m short in the
// rough, where it chipped again (and again: lw, lw, lw, putt in a seeded round).
TEST_CASE("a bot's chip over rough is planned to finish near the cup, not in the rough short of it", "[golf][bot]") {
  Course course = load_course(test::assets(), "national");
  course.holes = {course.holes[6]};
  course.holes[0].wind_speed = 0.0;
  const Terrain& world = *course.holes[0].world->world;
  SurfaceContact ball, cup;
  REQUIRE(ground_under(world, -37.54, -220.23, 400.0, 420.0, &ball));
  REQUIRE(ground_under(world, -26.0, -212.0, 400.0, 420.0, &cup));
  course.holes[0].tee = ball.point;
  course.holes[0].pin = cup.point;
  for (const char* skill : {"tour", "amateur"}) {
    const GolferSkill& g = golfer_skill(skill);
    const GolfRound round(test::assets(), course, g);
    REQUIRE(round.to_pin() == Approx(14.2).margin(0.2));
    const GolfBot bot(test::assets(), g, 1);
    const StrokeInput in = bot.intend(round);
    const ShotResult r = round.simulate(in);
    const Vec3& rest = r.trajectory.summary.rest_position;
    INFO(skill << ": " << in.club << " at " << in.meter.power << " power stops "
               << std::hypot(cup.point.x() - rest.x(), cup.point.z() - rest.z()) << " m away on the " << round.surface_at(rest));
    CHECK(in.meter.power < 1.0);
    CHECK(round.surface_at(rest) == "green");
    CHECK(std::hypot(cup.point.x() - rest.x(), cup.point.z() - rest.z()) < 2.5);
  }
}

TEST_CASE("the card keeps fairways hit and greens in regulation as the statistics count them", "[golf][round][card]") {
  // Hole 3, a par 5 with out of bounds all along the right: a driver 150 ms late is lost
  // right, and the tee shot counts as the miss even once the ball is played again.
  GolfRound late(test::assets(), one_hole(3), golfer_skill("tour"));
  REQUIRE(late.play(stroke("driver", 1.0, 150.0, 0.25)).end == StrokeEnd::OutOfBounds);
  CHECK(late.card()[0].tee_shot == TeeShot::Right);
  GolfBot caddie(test::assets(), golfer_skill("tour"), 1);
  late.play(caddie.intend(late));
  CHECK(late.card()[0].tee_shot == TeeShot::Right);
  // 150 ms early: hooked left into the rough or beyond.
  GolfRound early(test::assets(), one_hole(3), golfer_skill("tour"));
  early.play(stroke("driver", 1.0, -150.0));
  CHECK(early.card()[0].tee_shot == TeeShot::Left);
  // The caddie's plan struck perfectly finds the fairway, and the hole's greens in
  // regulation are counted from where each stroke comes to rest: on the green in three.
  GolfRound straight(test::assets(), one_hole(3), golfer_skill("tour"));
  const StrokeRecord& drive = straight.play(caddie.intend(straight));
  CHECK(straight.card()[0].tee_shot == TeeShot::Fairway);
  CHECK(straight.surface_at(drive.rest) == "fairway");
  int strokes = 1;
  bool reached = false;
  while (!straight.finished() && !reached) {
    const StrokeRecord& r = straight.play(caddie.intend(straight));
    strokes += 1 + r.penalty;
    reached = r.end == StrokeEnd::Holed || (!straight.finished() && straight.lie() == "green");
  }
  REQUIRE(reached);
  CHECK(straight.card()[0].green_in_regulation == (strokes <= 3));

  // A par 3 has no fairway. Into the pond and dropped: two strokes before the next, so the
  // green is not reached in regulation whatever follows.
  GolfRound wet(test::assets(), one_hole(1), golfer_skill("tour"));
  REQUIRE(wet.play(stroke("7-iron", 0.72)).end == StrokeEnd::Water);
  while (!wet.finished()) wet.play(caddie.intend(wet));
  CHECK(wet.card()[0].tee_shot == TeeShot::None);
  CHECK(!wet.card()[0].green_in_regulation);
  // Struck as planned, the par 3's tee shot finds the green: in regulation.
  GolfRound dry(test::assets(), one_hole(1), golfer_skill("tour"));
  dry.play(caddie.intend(dry));
  CHECK(dry.lie() == "green");
  CHECK(dry.card()[0].green_in_regulation);
}

TEST_CASE("a bot takes enough club that its usual short one still reaches the green", "[golf][bot]") {
  // The National's 6th with the day's cup (pin set 2), cut 3 m inside the front of the green
  // behind rough: the tour bot's plan, and the same plan struck a power standard deviation
  // short (the skill's spread, a part swing's more), both finish on the green.
  Course national = load_course(test::assets(), "national");
  CourseSetup day;
  day.pin_set = CourseSetup::kDayPinSet;
  set_up(national, day);
  Course sixth = national;
  sixth.holes = {national.holes[5]};
  sixth.holes[0].number = 1;
  const GolferSkill& g = golfer_skill("tour");
  GolfRound round(test::assets(), sixth, g);
  const GolfBot bot(test::assets(), g, 1);
  StrokeInput in = bot.intend(round);
  const double spread = g.power_sd + g.partial_feel_sd * (1.0 - std::min(in.meter.power, 1.0));
  INFO(in.club << " at " << in.meter.power);
  const ShotResult planned = round.simulate(in);
  CHECK(round.surface_at(planned.trajectory.summary.rest_position) == "green");
  in.meter.power *= 1.0 - spread;
  const ShotResult short_one = round.simulate(in);
  CHECK(round.surface_at(short_one.trajectory.summary.rest_position) == "green");
}
