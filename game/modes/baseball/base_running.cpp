#include "game/modes/baseball/base_running.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>

#include "game/content/resolve.hpp"

namespace sweetspot {
namespace {

// A runner's lead when the ball is hit. Off first and third: his primary lead at the pitcher's
// first move (Statcast's lead distance, ~10-12 ft off first; C. Moeller's coaching: three
// yard-long steps, 10-12 ft) and the secondary lead he shuffles out while the pitch is on its
// way, two shuffles landing as the ball reaches the hitting zone (coaching's universal rule;
// ESTIMATE of a shuffle: a yard, as the lead's steps), so ~17 ft at contact. Off second no one
// holds him on and he walks his lead out instead of holding it (ESTIMATE: ~18 ft at contact,
// Moeller's 15-18 ft lead off second).
constexpr double kSecondaryLead = 2.0 * 0.914;  // m
constexpr std::array<double, 3> kLead{3.4 + kSecondaryLead, 5.5, 3.4 + kSecondaryLead};  // m
constexpr double kRead = 0.3;          // s a runner takes to read a ball on the ground, or a catch (ESTIMATE)
// A ball in the air that no fielder could reach (Statcast's catch probability under kPlainHit)
// is read as a hit: the runners go once they have read it, kReadAir after contact, instead of
// holding until it drops (ESTIMATES).
constexpr double kPlainHit = 0.25;
constexpr double kReadAir = 1.0;       // s
constexpr double kLikelyCatch = 0.5;   // a ball more likely caught than not: the runners go back to their bases
// s before a catch that a runner who held or ran sees it coming (the fielder settling under
// the ball: kGatherUnder's 0.35 s and his last strides; ESTIMATE) and turns back.
constexpr double kSeesCatch = 1.0;
// Time to spare a runner is sent with for an extra base (or a tag): a coach sends him when he
// is likely safe. With the throw as it comes spread by kThrowSpread, a runner sent with
// 0.15 s to spare is safe ~3 times in 4 (ESTIMATE).
constexpr double kRunnerExtraBaseMargin = 0.15;
constexpr double kPivotExtra = 0.1;    // s the pivot man's turn takes beyond a clean transfer (ESTIMATE)

const char* base_name(int base) {
  static constexpr std::array<const char*, 5> kNames{"home", "1st", "2nd", "3rd", "home"};
  return kNames[static_cast<std::size_t>(std::clamp(base, 0, 4))];
}

// A runner is not at his top speed when he starts: from v0 he closes on it as a sprinter
// does, v(t) = v_max − (v_max − v0)·e^(−t/τ), and so covers d in d/v_max plus τ(1 − v0/v_max)
// once he is up to speed. τ from the steal: MLB's average steal time from the first move is
// 3.30 s from a 12 ft lead (Baseball Factory's scouting standard; coaches say 3.3-3.4 s); the
// 78 ft at the league's 27 ft/s sprint speed (Statcast) take 2.89 s at top speed, so τ ≈ 0.4 s
// (the slide's last steps inside it; at a base stealer's 28 ft/s it would be 0.5 s).
constexpr double kSprintTau = 0.4;  // s
// A runner on base is all but standing when the ball is hit: his secondary lead's shuffle
// lands as the ball reaches the zone (off second his walking lead, at a walk), ~1 m/s toward
// the next base (ESTIMATE); tagging up, or turned back to his base, he starts from rest.
constexpr double kShuffleSpeed = 1.0;  // m/s

}  // namespace

double sprint_time(double top_speed, double distance, double start_speed) {
  const double v = std::max(top_speed, 1.0);
  if (distance <= 0.0) return 0.0;
  const double lag = kSprintTau * (1.0 - std::clamp(start_speed, 0.0, v) / v);
  // Newton's method from the bound d/v + lag, which x(t) approaches from above: x(t) is
  // increasing and convex, so every step lands between the root and the last guess.
  double t = distance / v + lag;
  for (int i = 0; i < 8; ++i) {
    const double fade = std::exp(-t / kSprintTau);
    const double x = v * (t - lag * (1.0 - fade));
    const double dx = v * (1.0 - lag / kSprintTau * fade);
    if (dx <= 0.0) break;
    t -= (x - distance) / dx;
  }
  return t;
}

void HalfInning::advance(const PlateAppearance& pa, const Team& batting, const Team& fielding, Rng& throws,
                         std::vector<int>& scored, int& outs_made, std::string& description) {
  const PitchRecord& last = pa.pitches.back();
  const FieldingPlay& p = last.result.play;
  const int batter = pa.batter;
  const auto sprint = [&](int who) { return batting.lineup[static_cast<std::size_t>(who)].skill().sprint_speed; };
  const std::size_t fielder = static_cast<std::size_t>(std::max(p.fielder, 0));
  const FielderAbility& f = fielding.defense.ability[fielder];
  std::optional<Thrower> thrower;  // the fielder's arm, worked out at his first throw
  const auto apart = [](const Vec3& a, const Vec3& b) { return std::hypot(a.x() - b.x(), a.z() - b.z()); };
  // When the ball can be at base `to`: thrown there once the man covering it has run there
  // from where he stood when it was hit, or carried there by the fielder himself.
  const auto at_base = [&](int to, double ready) {
    const Vec3 base = base_position(to);
    const std::size_t c = static_cast<std::size_t>(covering_fielder(to, p.fielder));
    if (!thrower) thrower.emplace(fielder_thrower(f, *aero, environment));
    const double thrown = std::max(ready + throw_time(*thrower, p.fielded_at, to),
                                   fielder_run_time(fielding.defense.ability[c], apart(p.start[c], base)));
    const double carried = ready + fielder_run_time(f, apart(p.fielded_at, base)) - f.reaction;
    return std::min(thrown, carried);
  };
  // The seconds by which the runner from `from`, starting `start` s after contact `lead` m off
  // his base, beats the ball to `to` (negative: the ball is there first).
  const auto spare = [&](int who, int from, int to, double start, double lead, double ready) {
    const double from_speed = lead > 0.0 ? kShuffleSpeed : 0.0;  // off his lead, or tagging up from the bag
    const double dist = (to - from) * kBaseLine - lead;
    const double runner = start + sprint_time(sprint(who), dist, from_speed) + (to - from - 1) * kBaseRoundingTime;
    double ahead = at_base(to, ready) + kTagTime - runner;
    // A fielder with the ball beside the base path tags him on the way (a ball hit in front
    // of him): the nearest point of his last leg to the fielder, who starts from where he has it.
    const Vec3 a = base_position(to - 1), b = base_position(to);
    const Vec3 leg = (b - a) / kBaseLine;
    const double along = std::clamp((p.fielded_at - a).dot(leg), 0.0, kBaseLine);
    const Vec3 meet = a + along * leg;
    const double runner_there = start + sprint_time(sprint(who), (to - 1 - from) * kBaseLine + along - lead, from_speed) +
                                (to - from - 1) * kBaseRoundingTime;
    const double fielder_there = ready + fielder_run_time(f, apart(p.fielded_at, meet)) - f.reaction;
    return std::min(ahead, fielder_there - runner_there);
  };
  // The throw as it comes: safe when he beats it.
  const auto safe = [&](double estimate) { return estimate + throws.normal(kThrowSpread) > 0.0; };
  // The scorer's words for a throw to base `at`: "(RF to C)", "(1B unassisted)".
  const auto thrown_to = [&](int at) {
    const int takes = covering_fielder(at, p.fielder);
    return std::string(" (") + kPositionNames[fielder] +
           (takes == p.fielder ? std::string(" unassisted)") : std::string(" to ") + kPositionNames[static_cast<std::size_t>(takes)] + ")");
  };
  // A runner put out: his out, and the scorer's words for it after the batter's. Thrown out
  // advancing after the batter's own out (tagging up on a catch) he makes it a double play.
  std::string runner_out;
  const auto put_out = [&](int from, int at, bool batter_out = false) {
    ++outs;
    ++outs_made;
    runner_out = from == at ? std::string(", double play: runner doubled off ") + base_name(at) + thrown_to(at)
                            : std::string(", runner from ") + base_name(from) + " out at " + base_name(at) + thrown_to(at) +
                                  (batter_out ? ": double play" : "");
  };
  Bases next{-1, -1, -1};
  const auto place = [&](int who, int base) {
    if (base >= 4) scored.push_back(who);
    else next[static_cast<std::size_t>(base - 1)] = who;
  };

  // The game is over when the winning run scores (Rule 5.08(b)): no one is put out after it.
  const auto won = [&] { return runs_to_win > 0 && static_cast<int>(scored.size()) >= runs_to_win; };
  const BattedOutcome o = last.result.outcome;
  if (o == BattedOutcome::HomeRun || o == BattedOutcome::Triple || o == BattedOutcome::Double ||
      o == BattedOutcome::Single || o == BattedOutcome::Error) {
    const int hit = o == BattedOutcome::HomeRun ? 4 : o == BattedOutcome::Triple ? 3 : o == BattedOutcome::Double ? 2 : 1;
    // On a ball in the air runners hold at their leads until it drops, unless two are out
    // or it is plainly a hit.
    const double drops = last.result.shot.trajectory.summary.hang_time_s;
    const double start = (p.type == BattedBallType::GroundBall || outs == 2) ? kRead
                         : p.catch_probability < kPlainHit                    ? std::max(kRead, std::min(kReadAir, drops))
                                                                              : std::max(kRead, drops);
    for (int b = 3; b >= 1; --b) {
      const int who = bases[static_cast<std::size_t>(b - 1)];
      if (who < 0) continue;
      int to = std::min(4, b + hit);
      const bool open = to < 4 && (to + 1 > 3 || next[static_cast<std::size_t>(to)] < 0);
      if (open && o != BattedOutcome::Error && outs < 3 && runner_out.empty() && !won()) {
        const double s = spare(who, b, to + 1, start, kLead[static_cast<std::size_t>(b - 1)], p.ready_time);
        if (s > kRunnerExtraBaseMargin) {
          if (p.batter_out_at == 0 && !safe(s)) {  // the throw goes to the batter when he stretches
            put_out(b, to + 1);
            continue;
          }
          ++to;
        }
      }
      place(who, to);
    }
    if (p.batter_out_at > 0 && outs < 3 && !won()) {
      ++outs;
      ++outs_made;
      description += std::string(", out stretching at ") + base_name(p.batter_out_at) + thrown_to(p.batter_out_at);
    } else {
      place(batter, hit);
    }
    bases = next;
    description += runner_out;
    return;
  }

  if (p.caught) {
    ++outs;
    outs_made = 1;
    if (outs >= 3 || p.foul) return;
    // Caught: a runner who had left his base must get back before the throw beats him there.
    // On a ball he read as a likely catch he went back once he had read it; otherwise he held
    // at his lead until it would drop, or ran from kReadAir when it looked a plain hit, and
    // turns back when he sees the catch.
    const double caught = p.fielded_time;
    for (int b = 3; b >= 1 && outs < 3; --b) {
      const int who = bases[static_cast<std::size_t>(b - 1)];
      if (who < 0) continue;
      // (A liner is caught before he can see it coming: he turns at the catch.)
      const double turns =
          p.catch_probability >= kLikelyCatch ? 0.0 : caught - std::min(kSeesCatch, std::max(0.0, caught - kSeesCatch));
      double off = kLead[static_cast<std::size_t>(b - 1)];
      if (p.catch_probability < kPlainHit && turns > kReadAir) off += sprint(who) * (turns - kReadAir);
      off = std::min(off, kBaseLine);
      const double back = std::max(turns + kRead + sprint_time(sprint(who), off, 0.0), caught);
      const double throw_there = at_base(b, caught);
      if (!safe(throw_there - back)) {
        put_out(b, b);
        bases[static_cast<std::size_t>(b - 1)] = -1;
        break;  // one throw
      }
    }
    if (outs >= 3 || p.type == BattedBallType::PopUp || !runner_out.empty()) {
      description += runner_out;
      return;
    }
    // Runners on third and second tag up and go when the throw cannot beat them (the throw
    // goes to one base: the lead runner's, as the others are sent only behind him).
    if (bases[2] >= 0) {
      const double s = spare(bases[2], 3, 4, p.fielded_time, 0.0, p.fielded_time);
      if (s > kRunnerExtraBaseMargin) {
        if (safe(s)) scored.push_back(bases[2]);
        else put_out(3, 4, true);
        bases[2] = -1;
      }
    }
    // The throw went home if he was sent: the runner from second moves up behind it.
    if (outs < 3 && bases[1] >= 0 && bases[2] < 0) {
      const bool throw_home = !scored.empty() || !runner_out.empty();
      const double s = spare(bases[1], 2, 3, p.fielded_time, 0.0, p.fielded_time);
      if (throw_home || s > kRunnerExtraBaseMargin) {
        if (throw_home || safe(s)) bases[2] = bases[1];
        else put_out(2, 3, true);
        bases[1] = -1;
      }
    }
    description += runner_out;
    return;
  }

  // A ground ball out: with a runner forced at second and fewer than two out, the lead
  // runner first, then the relay to first for two when it beats the batter.
  if (outs < 2 && bases[0] >= 0) {
    const double runner = kRead + sprint_time(sprint(bases[0]), kBaseLine - kLead[0], kShuffleSpeed);
    const double at_second = at_base(2, p.ready_time);
    if (at_second < runner) {
      // The pivot at second: the second baseman when the shortstop or third baseman fields
      // it, the shortstop otherwise (a 6-4-3, a 5-4-3; a 4-6-3, a 3-6-3, a 1-6-3).
      const int pivot_at = covering_fielder(2, p.fielder);
      const FielderAbility& pivot = fielding.defense.ability[static_cast<std::size_t>(pivot_at)];
      const double at_first = at_second + kPivotExtra + throw_time(pivot, *aero, environment, base_position(2), 1);
      const bool double_play = at_first < p.batter_to_first && safe(p.batter_to_first - at_first);
      outs += double_play ? 2 : 1;
      outs_made = double_play ? 2 : 1;
      Bases nb{double_play ? -1 : batter, -1, -1};
      if (outs < 3) {
        if (bases[2] >= 0) scored.push_back(bases[2]);
        nb[2] = bases[1];
      } else {
        nb = {-1, bases[1], bases[2]};  // the inning is over: they are left on base
      }
      description = double_play ? "Grounded into a double play, " + std::string(kPositionNames[fielder]) + " to " +
                                      kPositionNames[static_cast<std::size_t>(pivot_at)] + " to 1B"
                                : "Fielder's choice, " + std::string(kPositionNames[fielder]) + " to " +
                                      kPositionNames[static_cast<std::size_t>(pivot_at)];  // the man covering second
      bases = nb;
      return;
    }
  }
  // The throw goes to first. Forced runners move up; a runner not forced goes on the ground
  // ball only when the throw to his base could not beat him (a ball hit behind him), and the
  // fielder who sees him go throws there instead when it gets him.
  if (outs >= 2) {
    ++outs;
    outs_made = 1;
    return;
  }
  const bool forced2 = bases[0] >= 0, forced3 = forced2 && bases[1] >= 0;
  Bases nb{-1, -1, -1};
  bool thrown_elsewhere = false;
  if (const int who = bases[2]; who >= 0) {
    const double s = forced3 ? 0.0 : spare(who, 3, 4, kRead, kLead[2], p.ready_time);
    if (forced3) {
      scored.push_back(who);
    } else if (s <= kRunnerExtraBaseMargin) {
      nb[2] = who;  // he holds
    } else if (safe(s)) {
      scored.push_back(who);
    } else {
      put_out(3, 4);
      thrown_elsewhere = true;
    }
  }
  if (const int who = bases[1]; who >= 0) {
    const bool open = nb[2] < 0;
    const double s = forced2 || !open ? 0.0 : spare(who, 2, 3, kRead, kLead[1], p.ready_time);
    if (forced2) {
      nb[2] = who;
    } else if (!open || s <= kRunnerExtraBaseMargin) {
      nb[1] = who;  // he holds
    } else if (thrown_elsewhere || safe(s)) {
      nb[2] = who;
    } else {
      put_out(2, 3);
      thrown_elsewhere = true;
    }
  }
  if (bases[0] >= 0) nb[1] = bases[0];
  if (thrown_elsewhere) {
    // The fielder's choice: the batter is safe at first.
    nb[0] = batter;
    description = "Fielder's choice" + runner_out;
  } else {
    ++outs;
    outs_made = 1;
  }
  bases = nb;
}

int runners_on(const Bases& b) { return static_cast<int>(std::count_if(b.begin(), b.end(), [](int r) { return r >= 0; })); }

HalfInning empty_half_inning(const Assets& assets) {
  ShotSpec spec;
  spec.sport = "baseball";
  spec.strike = LaunchStrike{};
  const ResolvedShot r = resolve(spec, assets);
  HalfInning h;
  h.aero = r.aero;
  h.environment = r.spec.environment;
  return h;
}

}  // namespace sweetspot
