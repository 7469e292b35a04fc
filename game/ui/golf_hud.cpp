// The golf HUD, meter, launch-monitor panel, wind arrow and scorecard (ImGui).
#include <imgui.h>

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <cstdio>
#include <limits>
#include <span>
#include <string>
#include <vector>

#include "game/modes/golf/standings.hpp"
#include "game/modes/replay.hpp"
#include "game/report/round_json.hpp"
#include "game/ui/golf_draw.hpp"
#include "game/ui/two_lines.hpp"
#include "game/ui/wrapped_text.hpp"
#include "physics/units.hpp"

namespace sweetspot {

std::string GolfUnits::distance(double m) const {
  char b[32];
  std::snprintf(b, sizeof b, imperial ? "%.0f yd" : "%.0f m", imperial ? m_to_yd(m) : m);
  return b;
}

std::string GolfUnits::putt(double m) const {
  char b[32];
  // Inside a foot (a tap-in) in inches, and in centimetres inside a metre: "0 ft" from the pin
  // read as holed when it was not.
  if (imperial && m_to_ft(m) < 0.95) std::snprintf(b, sizeof b, "%.0f in", std::max(1.0, std::round(m / 0.0254)));
  else if (imperial) std::snprintf(b, sizeof b, "%.0f ft", m_to_ft(m));
  else if (m < 0.95) std::snprintf(b, sizeof b, "%.0f cm", std::max(1.0, std::round(100.0 * m)));
  else std::snprintf(b, sizeof b, "%.1f m", m);
  return b;
}

std::string GolfUnits::course(double m) const { return course(m, m); }
std::string GolfUnits::course(double m, double longest) const { return longest < kNear ? putt(m) : distance(m); }

// A share of the carry from here worth naming (m, ~3 yd): under it the wind's or the ground's
// part is inside a good player's carry spread with one club (a few yards).
constexpr double kShareNoted = 2.7;

std::string why_from_here(double stock, bool measured, double here, double calm, const GolfUnits& units, const char* ground) {
  // Each share is the difference of two figures as the panel shows them (whole yards or
  // metres), so the named shares add up to "from here" less "stock" however each rounds.
  const auto shown = [&](double m) { return std::lround(units.imperial ? m_to_yd(m) : m); };
  std::string out;
  const auto share = [&](const std::string& what, long d) {
    if (d == 0) return;
    out += (out.empty() ? ": " : ", ") + what + (d > 0 ? " +" : " -") + std::to_string(std::abs(d)) + (units.imperial ? " yd" : " m");
  };
  if (std::isnan(calm)) {  // no still-air flight to part them by: the two together
    if (!measured && std::abs(here - stock) >= kShareNoted) share(std::string("wind, ") + ground, shown(here) - shown(stock));
    return out;
  }
  // Once one share is worth naming, the other is too from a whole unit up, so the line adds
  // up ("stock 78 yd; from here 68 yd: wind -2 yd, lie and slope -8 yd", not the ground's alone).
  const bool named = std::abs(here - calm) >= kShareNoted || (!measured && std::abs(calm - stock) >= kShareNoted);
  if (!named) return out;
  share("wind", shown(here) - shown(calm));
  if (!measured) share(ground, shown(calm) - shown(stock));
  return out;
}

const char* ground_share_words(const std::string& lie, double rise, bool splash) {
  // A splash's sand takes most of the carry: name it, not the slope.
  if (splash) return "splash and slope";
  // Under a metre of rise a carry changes by less than kShareNoted: nothing to name it by.
  constexpr double kRiseNoted = 1.0;  // m
  const bool clean = lie == "tee" || lie == "fairway" || lie == "green";
  if (clean && rise >= kRiseNoted) return "uphill";
  if (clean && rise <= -kRiseNoted) return "downhill";
  return "lie and slope";
}

std::string break_length(double m, const GolfUnits& units) {
  char by[24];
  if (units.imperial && m < 0.9144) std::snprintf(by, sizeof by, "%.0f in", std::max(1.0, m / 0.0254));
  else if (!units.imperial && m < 1.0) std::snprintf(by, sizeof by, "%.0f cm", std::max(1.0, 100.0 * m));
  else std::snprintf(by, sizeof by, "%s", units.putt(m).c_str());
  return by;
}

namespace {
// A break in the units a golfer reads a putt in (inches, centimetres) and in cups: the cup is
// 108 mm across (Rules of Golf, Definitions "Hole"). An aim within an eighth of it of the
// centre is "at the cup"; out to a quarter, "inside left" or "inside right" (a golfer's
// words for a point in the cup beside its centre), in the caddie's read and on the aim line
// alike: a 3 ft putt aimed 21 mm left read "straight: at the cup" beside arrows that showed
// the slope across it.
constexpr double kCup = 0.108;             // m
constexpr double kCentre = 0.125 * kCup;   // m
constexpr double kStraight = 0.25 * kCup;  // m
}  // namespace

std::string putt_read_words(const GolfPlay::PuttRead& read, const GolfUnits& units) {
  const double off = std::abs(read.aim_off);
  char aim[96];
  if (off < kCentre) {
    std::snprintf(aim, sizeof aim, "straight: at the cup");
  } else if (off < kStraight) {
    // Aimed left of the centre the ball must come back right: it breaks left to right.
    std::snprintf(aim, sizeof aim, "barely breaks %s: aim inside %s", read.aim_off < 0.0 ? "left to right" : "right to left",
                  read.aim_off < 0.0 ? "left" : "right");
  } else {
    const std::string by = break_length(off, units);
    const double cups = std::max(0.5, std::round(2.0 * off / kCup) / 2.0);
    // Aimed left of the cup the ball must come back right: it breaks left to right.
    std::snprintf(aim, sizeof aim, "breaks %s: aim %s %s (%g cup%s)", read.aim_off < 0.0 ? "left to right" : "right to left",
                  by.c_str(), read.aim_off < 0.0 ? "left" : "right", cups, cups > 1.0 ? "s" : "");
  }
  // His pace against the putt's length: uphill it must be struck as a longer putt on flat.
  std::string pace;
  if (read.plays_as > 0.0) {
    // m: within it the pace is the length's; at least the half foot the pace's words round to
    // (a 2 ft putt struck as 3 ft is uphill). Within the wider margin, "slightly": a 53 ft
    // putt played as 49 ft is not level to a golfer, nor is it a downhill putt.
    const double margin = std::max(0.15, 0.03 * read.to_cup), wide = std::max(0.15, 0.08 * read.to_cup);
    const double by = read.plays_as - read.to_cup;
    const char* slope = by > wide ? "uphill" : by < -wide ? "downhill" : by > margin ? "slightly uphill" : by < -margin ? "slightly downhill" : "level";
    pace = std::string(", ") + slope + ": play it as " + units.putt(read.plays_as) + " on the flat" +
           (read.power >= MeterInput::kPower.max - 1e-9 ? " (beyond a full putt: the blue mark at the end)" : " (blue mark)");
  }
  return std::string(aim) + pace + (read.holes ? "" : "; the caddie's best line, it may not drop");
}

std::string GolfUnits::speed(double mps) const {
  // A putt's few m/s get their tenth (a 1.4 m/s putt does not read "1 m/s").
  const double v = imperial ? mps_to_mph(mps) : mps;
  char b[32];
  std::snprintf(b, sizeof b, v < 10.0 ? (imperial ? "%.1f mph" : "%.1f m/s") : (imperial ? "%.0f mph" : "%.0f m/s"), v);
  return b;
}

namespace {

// The words around the meter sit on a dark band so the view behind (a green's slope arrows,
// sand, sky) never runs through them.
constexpr ImU32 kBand = IM_COL32(15, 20, 25, 170);

// The band under the meter that reads a power as a length (a putt's roll, a swing's carry):
// a tick at each length's power, and its label where no label placed before it would overlap
// and, when `right` is given, inside the band's right edge. Labels are placed in the order of
// their `rank` (lowest first; by default left to right), so the ones that matter most (a
// chip's lengths nearest the pin) are the ones kept where they crowd.
class MeterScale {
 public:
  MeterScale(ImDrawList* dl, const MeterBar& bar, float right = 1e9f) : dl_(dl), bar_(bar), right_(right) {
    dl_->AddRectFilled(ImVec2(bar.x0 - 4, bar.y0 + bar.bh + 2), ImVec2(bar.x0 + bar.bw + 4, bar.y0 + bar.bh + 24), kBand, 4.0f);
  }
  MeterScale(const MeterScale&) = delete;
  MeterScale& operator=(const MeterScale&) = delete;
  ~MeterScale() {
    std::stable_sort(labels_.begin(), labels_.end(), [](const Label& a, const Label& b) { return a.rank < b.rank; });
    std::vector<std::pair<float, float>> taken = named_;
    const float y = bar_.y0 + bar_.bh;
    for (const Label& l : labels_) {
      const float wide = ImGui::CalcTextSize(l.text.c_str()).x;
      const float from = l.x - 8.0f, to = from + wide + 5.0f;
      if (from + wide > right_) continue;
      if (std::any_of(taken.begin(), taken.end(), [&](const auto& t) { return from < t.second && to > t.first; })) continue;
      dl_->AddText(ImVec2(from, y + 7), IM_COL32(200, 200, 200, 220), l.text.c_str());
      taken.emplace_back(from, to);
    }
  }
  void tick(double power, const char* label = nullptr, double rank = std::numeric_limits<double>::quiet_NaN()) {
    if (power > bar_.high + 1e-9) return;  // past a zoomed bar's end
    const float x = bar_.at(power), y = bar_.y0 + bar_.bh;
    dl_->AddLine(ImVec2(x, y), ImVec2(x, y + 6), IM_COL32(200, 200, 200, 200), 1.0f);
    if (label == nullptr) return;
    labels_.push_back({x, label, std::isnan(rank) ? static_cast<double>(labels_.size()) : rank});
  }
  /// What the lengths are (a carry, or where the ball stops), at the band's left end, under
  /// the accuracy's stretch of the bar where no length is ticked.
  void name(const char* what) {
    const float y = bar_.y0 + bar_.bh;
    dl_->AddText(ImVec2(bar_.x0, y + 7), IM_COL32(160, 160, 160, 220), what);
    named_.emplace_back(bar_.x0, bar_.x0 + ImGui::CalcTextSize(what).x + 5.0f);
  }

 private:
  struct Label {
    float x;
    std::string text;
    double rank;
  };
  ImDrawList* dl_;
  const MeterBar& bar_;
  float right_;
  std::vector<Label> labels_;
  std::vector<std::pair<float, float>> named_;
};

// The power the player should strike for the target (a putt's cup, a swing's pin): a green
// line through the bar under a triangle, the caption naming it.
void target_mark(ImDrawList* dl, const MeterBar& bar, double power) {
  const ImU32 kTarget = IM_COL32(90, 225, 120, 255);
  const float x = bar.at(std::min(power, MeterBar::kHigh));
  dl->AddLine(ImVec2(x, bar.y0 - 2), ImVec2(x, bar.y0 + bar.bh + 2), kTarget, 2.0f);
  dl->AddTriangleFilled(ImVec2(x - 6, bar.y0 - 10), ImVec2(x + 6, bar.y0 - 10), ImVec2(x, bar.y0), kTarget);
}
// A run past the carry worth saying (m, 10 yd): a full iron's usual release on a fairway is
// less, a drive's or a flyer's from the rough more.
constexpr double kRunNoted = 9.144;

constexpr ImGuiWindowFlags kFixed = ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse;

const char* lie_words(const std::string& lie) {
  if (lie == "tee") return "Tee";
  if (lie == "fairway") return "Fairway";
  if (lie == "rough") return "Rough";
  if (lie == "sand") return "Bunker";
  if (lie == "green") return "Green";
  if (lie == "water") return "Water";
  if (lie == "out_of_bounds") return "Out of bounds";
  if (lie == "path") return "Cart path";
  return "?";
}

const char* camera_words(int mode) {
  switch (mode) {
    case 1: return "player";
    case 2: return "high";
    case 3: return "map";
    case 4: return "green";
  }
  return "?";
}

}  // namespace

Eigen::Vector4f draw_golf_hud(const GolfPlay& play, const GolfUnits& units, int camera_mode, bool settling, double flight_t,
                              bool all_keys) {
  const double now = flight_t;
  const GolfGroup& g = play.group();
  ImGui::SetNextWindowPos(ImVec2(10, 10), ImGuiCond_Always);
  // Narrower in the putting view (a putt, or a chip from where golfers count feet: the view
  // address_camera_at takes for both), which stands the golfer's head just right of it.
  const bool putting_view = !g.finished() &&
                            (play.stage() == GolfPlay::Stage::Aiming || play.stage() == GolfPlay::Stage::Swinging) &&
                            (play.round().lie() == "green" || play.round().to_pin() <= GolfUnits::kNear);
  // In a small window (the game allows 640 px) at most 42 % of its width, so the golfer and
  // the hole stay in view; its lines wrap instead.
  const float most = std::max(280.0f, 0.42f * ImGui::GetIO().DisplaySize.x);
  // Under 600 px of height (the game allows 480) the panel keeps to what its rows do not
  // already say, or its last lines run under the meter's caption.
  constexpr float kShortWindow = 600.0f;
  const bool short_window = ImGui::GetIO().DisplaySize.y < kShortWindow;
  ImGui::SetNextWindowSize(ImVec2(std::min(putting_view ? 345.0f : 420.0f, most), 0), ImGuiCond_Always);
  // Never down over the meter's caption: what does not fit scrolls (the hole, the lie and the
  // club stay at the top; a group's standings and the last stroke's lines go under).
  const ImVec2 screen = ImGui::GetIO().DisplaySize;
  const float room = meter_area(static_cast<int>(screen.x), static_cast<int>(screen.y))[1] - 10.0f - 6.0f;
  ImGui::SetNextWindowSizeConstraints(ImVec2(0.0f, 0.0f), ImVec2(FLT_MAX, std::max(160.0f, room)));
  ImGui::Begin("Play", nullptr, kFixed);
  const GolfPlay::Stage stage = play.stage();
  const bool in_air = stage == GolfPlay::Stage::Flying;
  const std::string& shooter = g.players()[static_cast<std::size_t>(play.shooter())].name;
  if (play.hole_shown() < g.course().holes.size()) {
    // The hole on screen: the card of one just finished names it, not the next.
    const CourseHole& hole = g.course().holes[play.hole_shown()];
    const CourseSetup& setup = g.course().setup;
    // Wrapped, as every line of the panel: a narrow window's panel cut "gimme 23 in" to "gi".
    if (!setup.tees.empty() || setup.pin_set > 1)
      ImGui::TextWrapped("%s   %s play   %s tees   pin set %d", g.course().name.c_str(), to_string(g.options().format),
                         setup.tees.empty() ? "own" : setup.tees.c_str(), setup.pin_set);
    else
      ImGui::TextWrapped("%s   %s play", g.course().name.c_str(), to_string(g.options().format));
    // A gimme's reach, rounded down (0.6 m is "23 in", not the "2 ft" a 0.62 m putt also reads).
    char gimme[40] = "";
    if (const double m = g.options().gimme_m; m > 0.0) {
      if (units.imperial) std::snprintf(gimme, sizeof gimme, "   gimme %.0f\u00a0in", std::floor(m / 0.0254 + 1e-9));
      else std::snprintf(gimme, sizeof gimme, "   gimme %.0f\u00a0cm", std::floor(100.0 * m + 1e-9));
    }
    ImGui::TextWrapped("Hole %d   Par %d   %s   Index %d%s", hole.number, hole.par, units.distance(hole.length()).c_str(),
                       hole.stroke_index, gimme);
  }
  if (stage == GolfPlay::Stage::Flyover) {
    ImGui::Separator();
    ImGui::Text("Flying the hole...   Enter: skip");
  } else if (in_air) {
    // The result waits until the ball stops: the HUD still shows the stroke being played.
    ImGui::Separator();
    const bool landed = now >= play.last_shot().trajectory.summary.hang_time_s;
    // A putt never leaves the green: it rolls from the start.
    const bool putt = play.last_shot().trajectory.summary.rolled_only();
    ImGui::Text("%s: the ball is %s", shooter.c_str(), putt ? "rolling" : landed ? "running out" : "in the air");
    disabled_wrapped(putt ? "Enter: skip the roll" : "Enter: skip the flight");
  } else if (settling) {
    // The ball has stopped: its result, before the next player's view.
    ImGui::Separator();
    ImGui::Text("%s: the ball is at rest", shooter.c_str());
  } else if (!g.finished() && (stage == GolfPlay::Stage::Aiming || stage == GolfPlay::Stage::Swinging)) {
    const GolfRound& r = play.round();
    ImGui::Separator();
    ImGui::Text("%s to play%s", play.player_info().name.c_str(), play.human_turn() ? "" : play.player_info().human ? " (auto-putt)" : " (bot)");
    const HoleCard& card = r.card().back();
    ImGui::Text("Stroke %d   Lie: %s", card.strokes + 1, lie_words(r.lie()));
    // From a bunker the club decides the technique (sand_entry_for): say which it will be.
    if (r.lie() == "sand" && play.club() != "putter")
      ImGui::TextWrapped("%s", r.sand_entry(play.club()) > 0.0
                                   ? "Splash: an inch of sand before the ball (about a third as far; late catches it clean and long, early takes more sand)"
                                   : "Picked clean, the ball first (the sand and lob wedges splash)");
    // On the green in the putt's units however long the putt.
    ImGui::Text("To the pin: %s", r.lie() == "green" ? units.putt(r.to_pin()).c_str() : units.course(r.to_pin()).c_str());
    const std::string& club = play.club();
    const GolfBot::Stock* stock = play.caddie().stock_of(club);
    const double carry = stock ? stock->carry : 0.0;
    // The bag's carry (calm air, flat fairway) and this swing's from here: the wind, the lie.
    const std::string name = club_name(club);
    const std::optional<double> part = play.caddie_part_swing(club);
    const bool part_swing = part && play.human_turn();
    if (club == "putter") ImGui::Text("Club: putter");
    else if (const std::optional<double> tree = play.tree_in_the_way(club))
      ImGui::TextWrapped("Club: %s (stock carry %s, a tree in the way at %s)", name.c_str(), units.distance(carry).c_str(),
                  units.distance(*tree).c_str());
    else if (part_swing)
      // The caddie's part swing is told on its own line below: a full swing's run ("stops
      // 99 yd") beside a 20 ft chip says nothing to the player.
      ImGui::TextWrapped("Club: %s (stock carry %s; full from here %s)", name.c_str(), units.distance(carry).c_str(),
                         units.distance(play.carry_here(club)).c_str());
    else {
      const double here = play.carry_here(club), stops = play.stops_here(club);
      const std::string why = why_from_here(carry, stock && stock->spread > 0.0, here, play.calm_carry_here(club), units,
                                            ground_share_words(r.lie(), play.landing_rise_here(club), r.sand_entry(club) > 0.0));
      // A run worth counting (the rough's flyer, a firm fairway), or one that takes a ball
      // landing short of the pin up toward it (a wedge that carries 65 yd of 76): where it
      // stops as well, the distance the caddie chose it by.
      if (stops - here >= kRunNoted || (here + kShareNoted < r.to_pin() && stops - here >= kShareNoted))
        ImGui::TextWrapped("Club: %s (stock carry %s; from here %s%s; stops %s)", name.c_str(), units.distance(carry).c_str(),
                           units.distance(here).c_str(), why.c_str(), units.distance(stops).c_str());
      else
        ImGui::TextWrapped("Club: %s (stock carry %s; from here %s%s)", name.c_str(), units.distance(carry).c_str(),
                           units.distance(here).c_str(), why.c_str());
    }
    // A part swing's feel: the power the caddie would give the club he chose (a pitch of
    // 29 yd with a 78 yd wedge is not a full swing), and where it lands and stops (the club
    // line's figures are the full swing's, which a part wedge from 80 yd flies well past).
    if (part_swing) {
      const double carries = play.carry_here(club, *part), stops = play.stops_here(club, *part);
      // In the unit "To the pin" is given in (feet inside GolfUnits::kNear): "To the pin:
      // 59 ft" over "stops 22 yd" mixed two for one chip.
      const double longest = r.to_pin();
      // Firmer than the pin's green mark (GolfBot::intend: where a short miss would finish on
      // worse ground, he swings a power spread harder): said, or the two marks read as a
      // contradiction.
      const auto pin = play.pin_power(club);
      const bool past = pin && *part > pin->power + 0.01 && stops > r.to_pin() + 1.0;
      ImGui::TextWrapped("Caddie: a part swing, %.0f %% power (blue mark): carries %s, stops %s%s", 100.0 * *part,
                         units.course(carries, longest).c_str(), units.course(stops, longest).c_str(),
                         past ? ", past the pin: a short one still gets there" : "");
    }
    // His club is not the one the distance asks for: say why, or the player takes the longer.
    if (const auto& plan = play.caddie_plan(); plan && plan->club == club && !play.caddie_passed_over().empty() && play.human_turn())
      ImGui::TextWrapped("Caddie: not the %s: struck a little off, it finds the trees", club_name(play.caddie_passed_over()).c_str());
    if (club == "putter" && r.lie() == "green") {
      // On the green the aim in the read's words: how far beside the cup the line points.
      const double off = r.to_pin() * std::tan(play.aim());
      const double deg = rad_to_deg(play.aim());
      if (std::abs(deg) < 0.05 || std::abs(off) < kCentre) ImGui::Text("Aim: at the cup");
      else if (std::abs(off) < kStraight) ImGui::Text("Aim: inside %s (%.1f deg %s)", off > 0.0 ? "right" : "left", std::abs(deg), off > 0.0 ? "right" : "left");
      else ImGui::Text("Aim: %s %s of the cup (%.1f deg)", break_length(std::abs(off), units).c_str(), off > 0.0 ? "right" : "left",
                       std::abs(deg));
    } else {
      // The caddie's aim off the pin says why; the player's own says nothing. Off the pin as a
      // golfer picks a target: how far beside the flag the line passes (14 deg is 7 yd on a
      // 29 yd pitch and 40 yd on a drive), the angle after it.
      const bool right = play.aim() >= 0.0;
      const char* why = "";
      switch (play.aim_why()) {
        case GolfPlay::AimWhy::Corner: why = "the dogleg's corner"; break;
        case GolfPlay::AimWhy::Bend: why = "down the fairway: the hole bends slightly"; break;
        case GolfPlay::AimWhy::WayOut: why = "the way past the tree"; break;
        case GolfPlay::AimWhy::Wind: why = right ? "the wind drifts it left" : "the wind drifts it right"; break;
        case GolfPlay::AimWhy::Slope: why = right ? "the slope brings it back left" : "the slope brings it back right"; break;
        case GolfPlay::AimWhy::Line: why = "where the caddie sees it finish nearest"; break;
        case GolfPlay::AimWhy::Pin: break;
      }
      const double deg = std::abs(rad_to_deg(play.aim()));
      // Beside the flag reads only where the flag is the target: within 45 deg of it, and
      // within the club's reach (its full swing stops within 15 % of the pin); a drive on a
      // par 5 is aimed at the fairway, and "278 yd left of the pin" says nothing.
      constexpr double kBesideReads = 45.0;  // deg
      constexpr double kReachShare = 1.15;
      // Out past a tree or at a dogleg's corner the target is the gap or the corner, not a
      // point beside the flag ("244 yd left of the pin" out of the trees): the angle, and what
      // the club's full swing down that line leaves to the pin (the triangle of its stop, the
      // pin and the ball).
      const bool elsewhere = play.aim_why() == GolfPlay::AimWhy::WayOut || play.aim_why() == GolfPlay::AimWhy::Corner;
      const double stops = play.stops_here(club);
      const bool flag_is_target = !elsewhere && deg < kBesideReads && r.to_pin() <= kReachShare * stops;
      const char* side = right ? "right" : "left";
      if (deg < 0.05) ImGui::Text("Aim: at the pin");  // "0.0 deg right" has no side
      // Wrapped: the caddie's reason runs past the panel's width.
      // Beside the flag by less than the unit's half: "0 yd left of the pin" is the pin.
      else if (flag_is_target && r.to_pin() * std::tan(deg_to_rad(deg)) < 0.5 * 0.9144)
        ImGui::TextWrapped("Aim: at the pin (%.1f deg %s%s%s)", deg, side, *why ? "; " : "", why);
      else if (flag_is_target)
        ImGui::TextWrapped("Aim: %s %s of the pin (%.1f deg%s%s)", units.course(r.to_pin() * std::tan(deg_to_rad(deg)), r.to_pin()).c_str(),
                           side, deg, *why ? "; " : "", why);
      else if (elsewhere) {
        const double pin = r.to_pin(), a = deg_to_rad(deg);
        const double leaves = std::sqrt(std::max(0.0, stops * stops + pin * pin - 2.0 * stops * pin * std::cos(a)));
        ImGui::TextWrapped("Aim: %.1f deg %s of the pin (%s; leaves %s)", deg, side, why, units.course(leaves).c_str());
      } else ImGui::TextWrapped("Aim: %.1f deg %s of the pin%s%s%s", deg, side, *why ? " (" : "", why, *why ? ")" : "");
    }
    if (play.human_turn() && club != "putter") {
      // What the caddie sees on the line and the low view from behind the ball can hide: each
      // stretch of water or sand from its near edge to its far one ("water 128-152 yd").
      std::string said;
      for (const GolfPlay::Hazard& hz : play.hazards_on_line(club)) {
        // In the unit the pin is given in, as the rest of the shot's distances.
        const double scale = std::max(hz.to, r.to_pin());
        const std::string near = units.course(hz.from, scale), far = units.course(hz.to, scale);
        const std::size_t cut = near.find(' ');
        const bool one_unit = cut != std::string::npos && far.size() > cut && far.substr(far.find(' ')) == near.substr(cut);
        // A stretch that reads one figure at both edges is said once ("sand 79 yd", not 79-79).
        said += std::string(said.empty() ? "" : ", ") + (hz.kind == "water" ? "water " : "sand ") +
                (near == far ? far : one_unit ? near.substr(0, cut) + "-" + far : near + " to " + far);
      }
      if (!said.empty()) ImGui::TextWrapped("On the line: %s", said.c_str());
    }
    if (const auto& read = play.putt_read(); read && play.human_turn())
      ImGui::TextWrapped("Read: %s", putt_read_words(*read, units).c_str());
    if (play.human_turn() && club == "putter" && r.lie() == "green") {
      // On the green the keys a putt needs, in one line: the panel stays clear of the golfer
      // the putting view frames under it; K/F1 adds the rest.
      // (The putting view's panel is narrow: each line under ~45 characters.)
      disabled_wrapped("Left/Right aim  Space putt  G read  B caddie");
      disabled_wrapped("Arrows: downhill, red steeper   K/F1 %s", all_keys ? "fewer" : "keys");
      if (all_keys) {
        disabled_wrapped("M map  1-4 cameras (%s)  U units", camera_words(camera_mode));
        disabled_wrapped("S save  L latency  R replay  Esc pause");
        disabled_wrapped("Tab next mode");
      }
      if (g.options().format == GolfFormat::Match) disabled_wrapped("H: concede the hole (asks first)");
    } else if (play.human_turn() && all_keys && putting_view) {
      // A chip in the putting view: the narrow panel's lines, each under ~45 characters, and
      // three of them, so the panel ends above the golfer's head (Tab and Esc are the pause
      // menu's, L the full-swing view's keys).
      disabled_wrapped("Up/Down club  Left/Right aim  C caddie's club");
      disabled_wrapped("Space swing (3 clicks)  B caddie  M map");
      disabled_wrapped("1-4 cameras  U units  S save  R replay  K/F1");
      if (g.options().format == GolfFormat::Match) disabled_wrapped("H: concede the hole (asks first)");
    } else if (play.human_turn() && all_keys) {
      disabled_wrapped("Up/Down club  Left/Right aim  C caddie's club");
      disabled_wrapped("Space: swing (3 clicks; putts 2)  B: caddie plays");
      disabled_wrapped("M map  1-4 cameras (%s)  U units  S save  L latency", camera_words(camera_mode));
      disabled_wrapped("R replay  Esc cancel or pause  Tab next mode  K/F1 fewer");
      if (g.options().format == GolfFormat::Match) disabled_wrapped("H: concede the hole (asks first)");
    } else if (play.human_turn()) {
      // Past the first hole the keys a stroke needs, in one line: the panel keeps to the
      // corner of the view (K brings the rest back).
      disabled_wrapped("Arrows club and aim  Space swing  B caddie  K/F1 keys");
    } else {
      disabled_wrapped("Enter: let them play now");
    }
  }
  // Each player's score so far against par.
  const Standings s = standings(g);
  // In a group, where each player is on this hole beside his score: the strokes played, how
  // far from the pin and on what, or how he finished it; a bot's ball is then not lost from
  // view when the camera has gone on to the next player.
  const bool group = g.players().size() > 1 && !g.finished();
  // In the air, the hole of the stroke (the model may already have moved the group on).
  const std::size_t hole = in_air ? play.hole_shown() : g.hole_index();
  const auto on_this_hole = [&](std::size_t p) -> std::string {
    if (!group) return {};
    // The stroke in the air is told when it stops, not before (the model has played it).
    if (in_air && static_cast<int>(p) == play.shooter()) return "   playing";
    const GolfRound& pr = g.round(static_cast<int>(p));
    if (pr.card().size() <= hole) return {};
    const HoleCard& c = pr.card()[hole];
    if (pr.finished() || pr.hole_index() > hole)
      return c.holed ? "   holed in " + std::to_string(c.strokes) : c.picked_up ? "   picked up" : "   conceded";
    if (c.strokes == 0) return "   to tee off";
    return "   " + std::to_string(c.strokes) + " played, " + (pr.lie() == "green" ? units.putt(pr.to_pin()) : units.course(pr.to_pin())) +
           " to go, " + lie_words(pr.lie());
  };
  if (s.holes > 0 || group) {
    ImGui::Separator();
    // The names' column as wide as the longest name: "You" beside "scratch bot" needs 11, and
    // a fixed 14 pushed the narrow putting panel's rows onto a second line.
    int name_w = 0;
    for (const GolfPlayer& pl : g.players()) name_w = std::max(name_w, static_cast<int>(pl.name.size()));
    for (std::size_t p = 0; p < g.players().size(); ++p) {
      const PlayerStanding& ps = s.players[p];
      char extra[48] = "";
      if (s.format == GolfFormat::Stableford) std::snprintf(extra, sizeof extra, "  %d pts", ps.total_points);
      if (s.format == GolfFormat::Skins && s.skins)
        std::snprintf(extra, sizeof extra, "  %d skin%s", s.skins->skins[p], s.skins->skins[p] == 1 ? "" : "s");
      const std::string here = on_this_hole(p);
      // The standings count the holes the whole group has finished; a player who has holed
      // out here while the others play on is told his total with this hole in it, beside
      // "holed in 2" (not the total before it, which reads as a stale sum).
      const bool untold = in_air && static_cast<int>(p) == play.shooter();
      const RunningTotal total = running_total(g, s, static_cast<int>(p), hole, untold);
      const int strokes = total.strokes, par = total.par, scored = total.holes;
      // Wrapped: a line that runs past the panel's edge ("3 ft to go, Gre") goes on below.
      char row[192];
      if (scored == 0)  // no hole scored yet (or a match's only one conceded): no score to stand on
        std::snprintf(row, sizeof row, "%-*s   -%s%s", name_w, g.players()[p].name.c_str(), extra, here.c_str());
      else
        std::snprintf(row, sizeof row, "%-*s %3d (%s)%s%s", name_w, g.players()[p].name.c_str(), strokes,
                      to_par_text(strokes - par).c_str(), extra, here.c_str());
      ImGui::TextWrapped("%s", row);
    }
    // Before the first hole is decided the match has no status of its own yet; while the
    // stroke that decides one is in the air, the status before it.
    if (s.match) {
      const std::size_t decided = std::min(s.match->holes.size(), in_air ? hole : s.match->holes.size());
      ImGui::Text("Match: %s", decided == 0 ? "all square" : s.match->holes[decided - 1].status.c_str());
    }
  } else if (g.options().format == GolfFormat::Match) {
    ImGui::Separator();
    ImGui::Text("Match: all square");
  }
  const auto at_rest = [&](const StrokeRecord& last, const std::string& lie) {
    if (last.club.empty() || last.end != StrokeEnd::Rest) return;
    // On the green in the putt's units, as the group's lines say the putt to come ("66 ft to go").
    const bool on_green = lie == "green" || lie == "holed";
    const std::string away = on_green ? units.putt(last.to_pin_m) : units.course(last.to_pin_m);
    // A ball at rest and then holed by a conceded putt (a gimme): where it stopped, on the green.
    if (lie == "holed") ImGui::TextWrapped("At rest %s from the pin: conceded", away.c_str());
    else if (last.club == "putter" && last.lie == "green")
      // A putt is judged by its pace: how far past the cup it ran, or how short it stopped,
      // along its line (the rest of the distance is the line's miss).
      ImGui::TextWrapped("At rest %s from the pin (%s %s), %s", away.c_str(), units.putt(std::abs(last.past_m)).c_str(),
                  last.past_m >= 0.0 ? "past" : "short", lie_words(lie));
    else {
      // Off the green a miss is read as a caddie reads it: long or short of the pin and to
      // which side, each named only where it is at least a third of the miss (a ball 38 ft
      // away, 36 of them short, is "short", not "short, left").
      const double miss = std::max(last.to_pin_m, 1e-9);
      std::string where;
      if (std::abs(last.past_m) >= miss / 3.0) where = last.past_m >= 0.0 ? "long" : "short";
      if (std::abs(last.right_m) >= miss / 3.0) where += std::string(where.empty() ? "" : ", ") + (last.right_m >= 0.0 ? "right" : "left");
      if (where.empty()) ImGui::TextWrapped("At rest %s from the pin, %s", away.c_str(), lie_words(lie));
      else ImGui::TextWrapped("At rest %s from the pin (%s), %s", away.c_str(), where.c_str(), lie_words(lie));
    }
  };
  if (!play.message().empty() && !in_air) {
    ImGui::Separator();
    ImGui::TextWrapped("%s", play.message().c_str());
    // Where another player's ball stopped is in his row of the group's lines above: in the
    // putting view, whose narrow panel must end above the golfer's head, and in a short
    // window, whose panel must end above the meter's caption, not said twice.
    const bool others_in_rows = (putting_view || short_window) && group && play.human_turn() && play.shooter() != play.player();
    if (play.message_is_result() && !others_in_rows) at_rest(play.last_record(), play.last_rest_lie());
  }
  // On your turn, your own last stroke on this hole, when somebody else has played since (in
  // a short window your row of the group's lines says where it lies).
  if (!in_air && play.human_turn() && play.shooter() != play.player() && !(short_window && group)) {
    if (const GolfPlay::OwnLast* mine = play.own_last(play.player())) {
      ImGui::Separator();
      // At a hot seat "your" is whoever is at the keys: named, unless it is "You".
      const std::string& name = play.player_info().name;
      const std::string whose = name == "You" ? std::string("Your") : name + "'s";
      ImGui::TextWrapped("%s last: %s", whose.c_str(), mine->message.c_str());
      at_rest(mine->record, mine->rest_lie);
    }
  }
  const ImVec2 at = ImGui::GetWindowPos(), size = ImGui::GetWindowSize();
  ImGui::End();
  return {at.x, at.y, at.x + size.x, at.y + size.y};
}

double zoomed_top(std::optional<double> pin_power) {
  constexpr double kMarkAt = 0.6, kLeast = 0.3;  // the mark's share of the zoomed bar; its least top
  if (!pin_power || *pin_power > 0.5 * MeterBar::kHigh) return MeterBar::kHigh;
  const double top = std::max(kLeast, std::ceil(10.0 * *pin_power / kMarkAt - 1e-9) / 10.0);
  return top >= 1.0 ? MeterBar::kHigh : top;
}

ClickMarks last_click_marks(const MeterClock& last, const MeterClock& next, double top) {
  ClickMarks m;
  if (last.putting() != next.putting()) return m;  // a wedge's power on the putt's scale would read as a length
  m.power = last.power() <= top + 1e-9;
  m.accuracy = !last.putting() && std::abs(last.tempo() - next.tempo()) <= 1e-9 * next.tempo();
  return m;
}

// px from the window's bottom to the meter bar's top (draw_meter_bar, meter_area).
constexpr float kMeterFromBottom = 80.0f;

Eigen::Vector4f meter_area(int w, int h) {
  // draw_meter_bar's geometry: the bar centred kMeterFromBottom up, two caption lines above
  // it, the power figure (~50 px) to its right, the scale under it.
  const float x0 = 0.5f * (static_cast<float>(w) - MeterBar{}.bw), y0 = static_cast<float>(h) - kMeterFromBottom;
  return {x0 - 6.0f, y0 - 60.0f, x0 + MeterBar{}.bw + 60.0f, static_cast<float>(h)};
}

MeterBar draw_meter_bar(const std::optional<MeterClock>& meter, const MeterClock& next, const std::optional<MeterClock>& last,
                        int w, int h, double now, double top) {
  const bool putting = next.putting();
  MeterBar bar;
  bar.high = top;
  bar.low = MeterBar::kLow * top / MeterBar::kHigh;
  bar.x0 = 0.5f * (static_cast<float>(w) - bar.bw);
  bar.y0 = static_cast<float>(h) - kMeterFromBottom;
  const float x0 = bar.x0, y0 = bar.y0, bw = bar.bw, bh = bar.bh;
  const auto at = [&](double f) { return bar.at(f); };
  ImDrawList* dl = ImGui::GetForegroundDrawList();
  // Opaque: a yardage stripe or its number on the ground behind it would read as a mark.
  dl->AddRectFilled(ImVec2(x0, y0), ImVec2(x0 + bw, y0 + bh), IM_COL32(20, 24, 30, 255), 4.0f);
  if (!putting) {
    // The accuracy mark, as wide as the difficulty's perfect window (at least a sliver).
    const double half = meter ? meter->window_fraction() : next.window_fraction();
    dl->AddRectFilled(ImVec2(at(-std::max(half, 0.006)), y0), ImVec2(at(std::max(half, 0.006)), y0 + bh), IM_COL32(60, 170, 80, 230));
  }
  if (!bar.zoomed()) dl->AddLine(ImVec2(at(1.0), y0 - 4), ImVec2(at(1.0), y0 + bh + 4), IM_COL32(250, 250, 250, 255), 2.0f);
  else {
    // A chip's zoomed bar: its end says what power it stands for, a marker past it stays there.
    char end[16];
    std::snprintf(end, sizeof end, "%.0f %%", 100.0 * bar.high);
    // On the bar's own dark ground: bare light text is lost over sand or a pale sky.
    const ImVec2 at_end(x0 + bw + 6.0f, y0 + 0.5f * (bh - ImGui::GetTextLineHeight()));
    const ImVec2 size = ImGui::CalcTextSize(end);
    dl->AddRectFilled(ImVec2(at_end.x - 3.0f, at_end.y - 2.0f), ImVec2(at_end.x + size.x + 3.0f, at_end.y + size.y + 2.0f),
                      IM_COL32(20, 24, 30, 255), 3.0f);
    dl->AddText(at_end, IM_COL32(230, 230, 230, 255), end);
  }
  if (meter) {
    const double p = meter->position(now);
    bar.shown = p;
    if (meter->phase() == MeterClock::Phase::Backswing)
      dl->AddRectFilled(ImVec2(at(0.0), y0 + 4), ImVec2(at(p), y0 + bh - 4), IM_COL32(230, 180, 40, 255));
    if (meter->phase() == MeterClock::Phase::Downswing) {
      dl->AddRectFilled(ImVec2(at(0.0), y0 + 4), ImVec2(at(meter->power()), y0 + bh - 4), IM_COL32(230, 180, 40, 120));
      // The power click's mark stays where it landed.
      dl->AddLine(ImVec2(at(meter->power()), y0 - 6), ImVec2(at(meter->power()), y0 + bh + 6), IM_COL32(255, 255, 255, 255), 3.0f);
      dl->AddLine(ImVec2(at(p), y0 - 6), ImVec2(at(p), y0 + bh + 6), IM_COL32(255, 80, 60, 255), 3.0f);
    }
  } else if (last) {
    // Where the last swing's clicks landed: power (white) and accuracy (red).
    const ClickMarks marks = last_click_marks(*last, next, top);
    if (marks.power)
      dl->AddLine(ImVec2(at(last->power()), y0 - 6), ImVec2(at(last->power()), y0 + bh + 6), IM_COL32(255, 255, 255, 150), 2.0f);
    if (marks.accuracy) {
      // A click past the bar's ends (up to 200 ms late) is marked at the end it went past.
      const double a = std::clamp(last->accuracy_position(), MeterBar::kLow, MeterBar::kHigh);
      dl->AddLine(ImVec2(at(a), y0 - 6), ImVec2(at(a), y0 + bh + 6), IM_COL32(255, 80, 60, 170), 2.0f);
    }
  }
  return bar;
}

void draw_golf_meter(const GolfPlay& play, const GolfUnits& units, int w, int h, double now) {
  const GolfPlay::Stage stage = play.stage();
  if (!(stage == GolfPlay::Stage::Aiming || stage == GolfPlay::Stage::Swinging) || !play.human_turn()) return;
  const bool putting = play.club() == "putter";
  const auto& meter = play.meter();
  // The last clicks' marks: a putt's only for a putt on the same green by the same player.
  const std::optional<MeterClock> marks =
      play.last_click() && (!play.last_click()->putting() || play.last_click_here()) ? play.last_click() : std::nullopt;
  // A chip's bar zoomed on its few per cent, so its scale and its pin mark stand apart.
  const std::optional<GolfPlay::PinPower> pin = putting ? std::nullopt : play.pin_power(play.club());
  const double top = zoomed_top(pin ? std::optional<double>(pin->power) : std::nullopt);
  const MeterClock next = play.next_meter();
  const MeterBar bar = draw_meter_bar(meter, next, marks, w, h, now, top);
  const float y0 = bar.y0;
  const auto at = [&](double f) { return bar.at(f); };
  const double shown = bar.shown;
  ImDrawList* dl = ImGui::GetForegroundDrawList();
  char label[256];
  if (putting && !play.putt_guide()) {
    // A putter chosen far from the cup: no roll table this far out, so no scale nor marks.
    const std::string reach = units.imperial ? std::to_string(std::lround(GolfPlay::kPuttGuideReach / 0.3048)) + " ft"
                                             : std::to_string(std::lround(GolfPlay::kPuttGuideReach)) + " m";
    if (meter)
      std::snprintf(label, sizeof label, "putt: %.0f %%   Esc: cancel", 100.0 * shown);
    else
      std::snprintf(label, sizeof label, "putt: cup %s, beyond the putt guide (inside %s)   Space: putt   Up/Down club",
                    units.course(play.round().to_pin()).c_str(), reach.c_str());
  } else if (putting) {
    // The putt preview: how far each power rolls on a flat green of this speed.
    // A tick every 5 ft (2 m); labels at the same round lengths on every green, spaced as the
    // roll grows with the square of the stroke (the short putts' ticks stand apart, the long
    // ones crowd the bar's end), each drawn where the last leaves room.
    MeterScale scale(dl, bar);
    const double step = units.imperial ? 5.0 * 0.3048 : 2.0;
    static constexpr long kLabelledFt[] = {5, 10, 20, 30, 40, 60, 80, 100, 120};
    static constexpr long kLabelledM[] = {2, 4, 6, 10, 14, 20, 30, 40};
    for (double d = step; d < play.flat_roll(1.1); d += step) {
      const long n = std::lround(d / step);
      const long length = units.imperial ? 5 * n : 2 * n;
      const auto& labelled = units.imperial ? std::span<const long>(kLabelledFt) : std::span<const long>(kLabelledM);
      char text[16];
      std::snprintf(text, sizeof text, units.imperial ? "%ld ft" : "%ld m", length);
      const bool named = std::find(labelled.begin(), labelled.end(), length) != labelled.end();
      scale.tick(play.power_for_roll(d), named ? text : nullptr);
    }
    const double to_cup = play.round().to_pin();
    // Off the green the mark is for the putt as it plays: the slower grass first.
    const double plays = play.putt_plays_as();
    const double cup_p = play.cup_mark_power();
    const double past = GolfBot::kPuttPast;
    char cup[96];
    if (play.putt_crosses().empty())
      std::snprintf(cup, sizeof cup, "cup %s", units.putt(to_cup).c_str());
    else
      std::snprintf(cup, sizeof cup, "cup %s, plays as %s (%s first)", units.putt(to_cup).c_str(),
                    units.putt(plays).c_str(), play.putt_crosses().c_str());
    // The cup's mark in its own colour, through the bar (the caption, above it, names it):
    // white is the bar's 100 % line and the last putt's power, blue the caddie's read.
    target_mark(dl, bar, cup_p);
    if (meter) {
      std::snprintf(label, sizeof label, "putt: %.0f %% rolls %s on flat green (%s)   Esc: cancel", 100.0 * shown,
                    units.putt(play.flat_roll(shown)).c_str(), cup);
    } else {
      // Before the stroke the caption is always the cup's: the power that rolls the putt on
      // flat and 17 in past (the triangle); the last putt's power beside it, not in its place.
      char last[40] = "";
      if (marks && marks->putting()) std::snprintf(last, sizeof last, " (last putt %.0f %%)", 100.0 * marks->power());
      // Past the putter's longest stroke the mark sits at the bar's end: say so, not "110 %".
      const double reach = play.flat_roll(1.1);
      if (plays + past > reach)
        std::snprintf(label, sizeof label, "putt: %s, beyond a putt: 110 %% rolls %s on flat green%s   Space: putt", cup,
                      units.putt(reach).c_str(), last);
      else {
        // The caddie's read is a second mark (blue): named, so the two are not taken for one.
        char read[48] = "";
        if (const auto& rd = play.putt_read()) std::snprintf(read, sizeof read, "; blue: the caddie's read, %.0f %%", 100.0 * rd->power);
        // A short putt's marker climbs slower (MeterClock::putt_tempo), as a part swing's: said,
        // or the long putts' rhythm leaves it short.
        const bool slower = MeterClock::putt_tempo(cup_p) > MeterClock::tempo_for(true) + 1e-9;
        std::snprintf(label, sizeof label, "putt: %s; green: the cup mark, %.0f %% (%s past on the flat%s)%s%s   Space: putt", cup,
                      100.0 * cup_p, break_length(past, units).c_str(), slower ? "; a slower bar" : "", read, last);
      }
    }
  } else {
    // The swing's distance scale, as the putt's: how far each power carries from here (ticks
    // every 10 yd or m, labelled at round lengths where the last label leaves room), and the
    // power whose stroke stops at the pin (a ball that runs on is aimed by where it
    // finishes), a green mark as the putt's cup, when the club gets there. Kept while a
    // swing that was abandoned is said in the caption.
    const std::string& club = play.club();
    const double longest = play.carry_at_power(club, MeterBar::kHigh);
    const double unit = units.imperial ? 0.9144 : 1.0;
    char pin_words[128] = "";
    const double to_pin = play.round().to_pin();
    if (longest > 10.0 * unit) {
      MeterScale scale(dl, bar, bar.x0 + bar.bw + 4.0f);
      // Ticks every 10 yd (m) of carry, labelled every 20 for a wedge and 50 for the longer
      // clubs. Inside 50 yd the scale is where the ball stops, as the pin's mark is: a chip is
      // played to where it finishes, and its carry is the lesser part of it. Short of the pin
      // and some past it it steps as the player counts them, in the units the panel gives the
      // pin (feet inside GolfUnits::kNear: every 10 ft, labelled every 20; under 50 yd every
      // 5 yd, labelled every 10), so a 16 ft chip has a tick to aim by.
      const bool by_stop = to_pin < 45.72;  // m: 50 yd
      const auto power_for = [&](double m) { return by_stop ? play.power_for_stop(club, m) : play.power_for_carry(club, m); };
      scale.name(by_stop ? "stops" : "carry");
      const double reach = by_stop ? play.stop_at_power(club, MeterBar::kHigh) : longest;
      const bool feet = to_pin < GolfUnits::kNear;
      const double fine_unit = feet ? (units.imperial ? 0.3048 : 1.0) : unit;
      const long fine_step = feet ? (units.imperial ? 10 : 2) : 5, fine_every = 2 * fine_step;
      const double fine_to = by_stop ? std::max(2.0 * to_pin, to_pin + 10.0) : 0.0;
      const double first = 0.05;  // the table's lowest power: below it the scale is a guess
      for (long n = fine_step; n * fine_unit < std::min(fine_to, reach); n += fine_step) {
        const double p = power_for(n * fine_unit);
        if (p < first) continue;
        char text[16];
        std::snprintf(text, sizeof text, feet ? (units.imperial ? "%ld ft" : "%ld m") : (units.imperial ? "%ld yd" : "%ld m"), n);
        scale.tick(p, n % fine_every == 0 ? text : nullptr, std::abs(n * fine_unit - to_pin));
      }
      const long every = longest < 130.0 * unit ? 20 : 50;  // labels: a wedge's every 20, the longer clubs' every 50
      for (long n = 10; n * unit < reach; n += 10) {
        if (n * unit < fine_to) continue;  // told finer above
        const double p = power_for(n * unit);
        if (p < first) continue;
        char text[16];
        std::snprintf(text, sizeof text, units.imperial ? "%ld yd" : "%ld m", n);
        // Past a chip told in feet, ticks alone: one scale, one unit.
        scale.tick(p, n % every == 0 && !feet ? text : nullptr, by_stop ? std::abs(n * unit - to_pin) : static_cast<double>(n));
      }
      if (pin) {
        target_mark(dl, bar, pin->power);
        // Where no power stops at the pin (the stop jumps across it), the nearest and where it
        // stops: a mark that promised the pin would send the ball that far past or short.
        const double miss = pin->stops - to_pin;
        // Past full power the meter's overswing strays more (swing_meter.hpp): said, so a mark
        // at 106 % reads as "more club", not as a swing to make.
        const char* over = pin->power > 1.0 + 1e-9 ? " (an overswing: more club?)" : "";
        if (std::abs(miss) <= std::max(2.0, 0.04 * to_pin))
          std::snprintf(pin_words, sizeof pin_words, "; green: stops at the pin at %.0f %%%s", 100.0 * pin->power, over);
        else
          std::snprintf(pin_words, sizeof pin_words, "; green: nearest the pin, %.0f %% stops %s %s%s", 100.0 * pin->power,
                        units.course(std::abs(miss), to_pin).c_str(), miss > 0.0 ? "past" : "short", over);
      }
    }
    if (!meter && play.swing_undone()) {
      // Said where the player was looking when it happened, not only in the panel.
      std::snprintf(label, sizeof label, "%s", play.message().c_str());
    } else {
      // The last swing's two marks (draw_meter_bar) are named, as the putt's last power is.
      const ClickMarks shown_marks = marks ? last_click_marks(*marks, next, top) : ClickMarks{};
      const char* last_marks = shown_marks.accuracy && shown_marks.power ? "; white, red: your last clicks"
                               : shown_marks.power                       ? "; white: your last power"
                               : shown_marks.accuracy                    ? "; red: your last accuracy click"
                                                                         : "";
      // A part swing's bar climbs slower (MeterClock::part_swing_tempo: the blue mark takes
      // 0.6 s to reach): said before the swing, so the change of pace is not a surprise.
      const std::optional<double> part = play.caddie_part_swing(club);
      const bool slowed = part && MeterClock::part_swing_tempo(*part) > MeterClock::tempo_for(false) + 1e-9;
      char before[240];
      std::snprintf(before, sizeof before, "%s: Space to swing (%s: perfect within %.0f ms%s)%s%s", club_name(club).c_str(),
                    to_string(play.setup().difficulty), perfect_window_ms(play.setup().difficulty),
                    slowed ? "; part swing: a slower bar" : "", pin_words, last_marks);
      std::snprintf(label, sizeof label, "%s", full_swing_caption(meter, now, before).c_str());
    }
  }
  // The caddie's part swing (his club, under full power), or his pace for a putt he read: a
  // mark on the bar where his power is, as the putt's cup is marked, so "Caddie: a part
  // swing, 36 % power" has a target.
  std::optional<double> caddie_power;
  if (!putting) {
    caddie_power = play.caddie_part_swing(play.club());
  } else if (const auto& read = play.putt_read()) {
    caddie_power = std::min(read->power, MeterBar::kHigh);
  }
  if (caddie_power) {
    const float x = at(*caddie_power);
    dl->AddTriangleFilled(ImVec2(x - 6, y0 - 10), ImVec2(x + 6, y0 - 10), ImVec2(x, y0), IM_COL32(120, 220, 255, 255));
  }
  draw_meter_caption(bar, label);
}

std::string full_swing_caption(const std::optional<MeterClock>& meter, double now, const std::string& before) {
  if (!meter) return before;
  char label[128];
  if (meter->phase() == MeterClock::Phase::Downswing)
    // The power is set: the marker on its way back is the accuracy's, not a power.
    // It comes back 1.5x as fast as it went up (MeterClock::kDownFactor): said, or the first
    // accuracy click of a newcomer's round comes late.
    std::snprintf(label, sizeof label, "power %.0f %%, accuracy next: Space at the mark, it comes back faster   Esc: cancel",
                  100.0 * meter->power());
  else
    std::snprintf(label, sizeof label, "power %.0f %%   Esc: cancel", 100.0 * meter->position(now));
  return label;
}

void draw_meter_caption(const MeterBar& bar, const std::string& text) {
  ImDrawList* dl = ImGui::GetForegroundDrawList();
  // Over the bar: cut in two at a clause break when it is wider than the bar (a chip's
  // caption ran 1035 px over a 560 px bar, out to a 1280 px window's edge), and moved left
  // when it still runs past the window's right edge.
  const float window = ImGui::GetIO().DisplaySize.x;
  const auto width = [](std::string_view s) { return ImGui::CalcTextSize(s.data(), s.data() + s.size()).x; };
  std::pair<std::string, std::string> lines{text, ""};
  if (width(text) > std::min(bar.bw + 40.0f, window - 16.0f)) lines = split_in_two_lines(text, width);
  const float line = ImGui::GetTextLineHeight();
  const float wide = std::max(width(lines.first), width(lines.second));
  const float x = std::max(8.0f, std::min(bar.x0, window - 8.0f - wide));
  const float top = bar.y0 - 26.0f - (lines.second.empty() ? 0.0f : line);
  dl->AddRectFilled(ImVec2(x - 4, top - 2), ImVec2(x + wide + 4, bar.y0 - 24 + line), kBand, 4.0f);
  dl->AddText(ImVec2(x, top), IM_COL32(255, 255, 255, 255), lines.first.c_str());
  if (!lines.second.empty()) dl->AddText(ImVec2(x, top + line), IM_COL32(255, 255, 255, 255), lines.second.c_str());
}

void draw_launch_panel(const ShotResult& r, const GolfUnits& units, int w, double flight_t, bool hit_tree, float top) {
  ImGui::SetNextWindowPos(ImVec2(static_cast<float>(w) - 250, top), ImGuiCond_Always);
  ImGui::SetNextWindowSize(ImVec2(240, 0), ImGuiCond_Always);
  ImGui::Begin("Launch monitor", nullptr, kFixed);
  if (r.club.speed > 0.0 && r.trajectory.summary.apex_m >= 0.05) {  // a full or part swing: the club's numbers too
    ImGui::Text("Club speed  %s", units.speed(r.club.speed_at_impact).c_str());  // after a lie's loss, as smash divides by
    ImGui::Text("Smash       %.2f", r.smash_factor);
  }
  ImGui::Text("Ball speed  %s", units.speed(r.launch.ball_speed).c_str());
  ImGui::Text("Launch      %.1f deg", rad_to_deg(r.launch.vertical_angle));
  // An angle by side, to a tenth: one that rounds to 0.0 has none (no "-0.0" for a putt).
  const auto by_side = [](double rad) {
    const double deg = std::round(10.0 * rad_to_deg(rad)) / 10.0;
    char t[32];
    std::snprintf(t, sizeof t, "%.1f deg%s", std::abs(deg), deg > 0.0 ? " R" : deg < 0.0 ? " L" : "");
    return std::string(t);
  };
  ImGui::Text("Direction   %s", by_side(r.launch.horizontal_angle).c_str());
  ImGui::Text("Spin        %.0f rpm", radps_to_rpm(r.launch.spin.total));
  // Tilted right (+) the ball curves right: said by side as the direction is.
  ImGui::Text("Spin axis   %s", by_side(r.launch.spin.axis_rad).c_str());
  const bool putt = r.trajectory.summary.rolled_only();
  if (putt && flight_t >= duration(r.trajectory)) {
    ImGui::Separator();
    ImGui::Text("Rolled      %s", units.putt(r.trajectory.summary.total_m).c_str());
  } else if (!putt && flight_t >= r.trajectory.summary.hang_time_s) {
    ImGui::Separator();
    // In the unit of the whole shot, as the landing ring's label: a chip that carries 11 m and
    // runs to 25 m reads "Carry 12 yd" beside its "12 yd" ring, not "36 ft".
    const FlightSummary& f = r.trajectory.summary;
    ImGui::Text(hit_tree ? "Hit a tree  %s" : "Carry       %s", units.course(f.carry_m, std::max(f.carry_m, f.total_m)).c_str());
    ImGui::Text("Height      %s", units.putt(r.trajectory.summary.apex_m).c_str());
  }
  ImGui::End();
}

double screen_up_heading(const Camera& cam) {
  const Vec3 up = cam.forward() + cam.true_up();
  return std::atan2(up.z(), up.x());
}

// The wind dial's centre: 60 px in from the right edge, 230 px down (draw_wind, wind_area).
ImVec2 wind_dial_centre(int w) { return ImVec2(static_cast<float>(w) - 60.0f, 230.0f); }

Eigen::Vector4f wind_area(int w) {
  // draw_wind's geometry: a 34 px dial, its label under it.
  const ImVec2 c = wind_dial_centre(w);
  return {c.x - 40.0f, c.y - 40.0f, static_cast<float>(w), c.y + 56.0f};
}

void draw_wind(const GolfPlay& play, const GolfUnits& units, int w, double screen_up) {
  const GolfGroup& g = play.group();
  if (g.finished() || play.hole_shown() >= g.winds().size()) return;
  // The hole the header names: while a finished hole's card shows, its wind, not the next's.
  const HoleWind wind = g.winds()[play.hole_shown()];
  ImDrawList* dl = ImGui::GetForegroundDrawList();
  const ImVec2 c = wind_dial_centre(w);
  dl->AddCircleFilled(c, 34.0f, IM_COL32(20, 24, 30, 200));
  char label[48];
  if (wind.speed < 0.5) {
    std::snprintf(label, sizeof label, "calm");
  } else {
    // Turned as the view is (behind the ball up the screen is the aim, on the map the hole's
    // line); the arrow points where the wind blows.
    const double rel = wind.toward - screen_up;
    const float dx = static_cast<float>(std::sin(rel)), dy = static_cast<float>(-std::cos(rel));
    const ImVec2 tip(c.x + 26 * dx, c.y + 26 * dy), tail(c.x - 26 * dx, c.y - 26 * dy);
    dl->AddLine(tail, tip, IM_COL32(120, 200, 255, 255), 3.0f);
    dl->AddTriangleFilled(tip, ImVec2(tip.x - 10 * dx - 6 * dy, tip.y - 10 * dy + 6 * dx),
                          ImVec2(tip.x - 10 * dx + 6 * dy, tip.y - 10 * dy - 6 * dx), IM_COL32(120, 200, 255, 255));
    std::snprintf(label, sizeof label, "wind %s", units.speed(wind.speed).c_str());
  }
  // A dark shadow under it: the label stands over trees and sky alike.
  dl->AddText(ImVec2(c.x - 29, c.y + 39), IM_COL32(0, 0, 0, 220), label);
  dl->AddText(ImVec2(c.x - 30, c.y + 38), IM_COL32(255, 255, 255, 255), label);
}

bool golf_card_covers_wind(int w) { return 0.5f * static_cast<float>(w) + 300.0f > wind_area(w)[0]; }

void draw_golf_card(const GolfPlay& play, int w, bool final) {
  const GolfGroup& g = play.group();
  const Standings s = standings(g);
  const std::size_t n = g.players().size();
  ImGui::SetNextWindowPos(ImVec2(0.5f * static_cast<float>(w) - 300, 150), ImGuiCond_Always);
  ImGui::SetNextWindowSize(ImVec2(600, 0), ImGuiCond_Always);
  // Opaque: the scene's labels (drawn under the windows) must not read through the card.
  ImGui::SetNextWindowBgAlpha(1.0f);
  ImGui::Begin(final ? "Final scorecard" : "Scorecard", nullptr, kFixed);
  const int cols = 3 + static_cast<int>(n) + (s.match || s.skins ? 1 : 0);
  if (ImGui::BeginTable("card", cols, ImGuiTableFlags_Borders | ImGuiTableFlags_RowBg)) {
    // The numbers and the match's words as wide as they are ("scratch bot 2 up (dormie)"
    // read whole); the players share the rest.
    const ImGuiTableColumnFlags fit = ImGuiTableColumnFlags_WidthFixed;
    ImGui::TableSetupColumn("Hole", fit);
    ImGui::TableSetupColumn("Par", fit);
    ImGui::TableSetupColumn("SI", fit);
    for (const GolfPlayer& p : g.players()) ImGui::TableSetupColumn(p.name.c_str(), ImGuiTableColumnFlags_WidthStretch);
    if (s.match) ImGui::TableSetupColumn("Match", fit);
    if (s.skins) ImGui::TableSetupColumn("Skin", fit);
    ImGui::TableHeadersRow();
    int par = 0;
    // A card past nine holes adds each nine, as a printed card does: "Out" under the 9th,
    // "In" under the last, each player's strokes (putts) over the holes he scored.
    const auto nine_row = [&](const char* label, std::size_t from, std::size_t to) {
      int nine_par = 0;
      for (std::size_t h = from; h < to; ++h) nine_par += g.course().holes[h].par;
      ImGui::TableNextRow();
      ImGui::TableNextColumn();
      ImGui::TextUnformatted(label);
      ImGui::TableNextColumn();
      ImGui::Text("%d", nine_par);
      ImGui::TableNextColumn();
      for (std::size_t p = 0; p < n; ++p) {
        ImGui::TableNextColumn();
        const PlayerStanding::Sum nine = s.players[p].sum(from, to);
        if (s.format == GolfFormat::Stableford) ImGui::Text("%d (%d) %dpt", nine.strokes, nine.putts, nine.points);
        else ImGui::Text("%d (%d)", nine.strokes, nine.putts);
      }
      if (s.match || s.skins) ImGui::TableNextColumn();
    };
    for (std::size_t h = 0; h < s.holes; ++h) {
      const CourseHole& ch = g.course().holes[h];
      par += ch.par;
      ImGui::TableNextRow();
      ImGui::TableNextColumn();
      if (play.restarts(h) > 0) ImGui::Text("%d R", ch.number);  // restarted: a mulligan
      else ImGui::Text("%d", ch.number);
      ImGui::TableNextColumn();
      ImGui::Text("%d", ch.par);
      ImGui::TableNextColumn();
      ImGui::Text("%d", ch.stroke_index);
      for (std::size_t p = 0; p < n; ++p) {
        ImGui::TableNextColumn();
        const HoleCard& c = g.round(static_cast<int>(p)).card()[h];
        const PlayerStanding& ps = s.players[p];
        char pts[16] = "", pen[16] = "";
        if (s.format == GolfFormat::Stableford) std::snprintf(pts, sizeof pts, " %dpt", ps.points[h]);
        if (c.penalties > 0) std::snprintf(pen, sizeof pen, " %dp", c.penalties);
        if (!ps.scored[h])
          ImGui::TextUnformatted(c.conceded ? "C" : "-");  // a match's hole conceded or left: no score
        else
          ImGui::Text("%d%.*s (%d)%s%s%s", ps.gross[h], std::min(ps.received[h], 4), "****", ps.putts[h], pen, pts,
                      c.picked_up ? " PU" : "");
      }
      if (s.match) {
        ImGui::TableNextColumn();
        ImGui::TextUnformatted(s.match->holes[h].status.c_str());
      }
      if (s.skins) {
        ImGui::TableNextColumn();
        const int win = s.skins->winner[h];
        if (win < 0) ImGui::TextUnformatted("carried");
        else ImGui::Text("%s x%d", g.players()[static_cast<std::size_t>(win)].name.c_str(), s.skins->value[h]);
      }
      if (s.holes > 9 && h == 8) nine_row("Out", 0, 9);
    }
    if (s.holes > 9) nine_row("In", 9, s.holes);
    // The sum rows: strokes (with par), putts, fairways hit and greens in regulation, to par,
    // net, points.
    auto sum_row = [&](const char* label, const char* par_text, auto cell) {
      ImGui::TableNextRow();
      ImGui::TableNextColumn();
      ImGui::TextUnformatted(label);
      ImGui::TableNextColumn();
      ImGui::TextUnformatted(par_text);
      ImGui::TableNextColumn();
      for (std::size_t p = 0; p < n; ++p) {
        ImGui::TableNextColumn();
        // No hole scored yet (a match's first hole conceded): no sums, not zeros.
        const PlayerStanding& ps = s.players[p];
        ImGui::TextUnformatted(ps.holes_scored == 0 && s.holes > 0 ? "-" : cell(ps).c_str());
      }
      if (s.match || s.skins) ImGui::TableNextColumn();
    };
    const std::string par_text = std::to_string(par);
    sum_row("Total", par_text.c_str(), [&](const PlayerStanding& ps) { return ps.total_text(s.holes); });
    sum_row("Putts", "", [](const PlayerStanding& ps) { return std::to_string(ps.total_putts); });
    sum_row("Fairways", "", [](const PlayerStanding& ps) { return std::to_string(ps.fairways_hit) + "/" + std::to_string(ps.fairways); });
    sum_row("Greens", "", [&](const PlayerStanding& ps) { return std::to_string(ps.greens_in_regulation) + "/" + std::to_string(ps.greens); });
    sum_row("To par", "", [](const PlayerStanding& ps) { return to_par_text(ps.total_strokes - ps.total_par); });
    sum_row("Net", "", [](const PlayerStanding& ps) { return std::to_string(ps.total_net); });
    if (s.format == GolfFormat::Stableford)
      sum_row("Points", "", [](const PlayerStanding& ps) { return std::to_string(ps.total_points); });
    if (s.skins) {
      sum_row("Skins", "", [&](const PlayerStanding& ps) {
        const std::size_t p = static_cast<std::size_t>(&ps - s.players.data());
        return std::to_string(s.skins->skins[p]);
      });
    }
    ImGui::EndTable();
  }
  // The key says only what the card shows: strokes received, penalties, pick-ups, concessions.
  bool received = false, picked_up = false, conceded = false, penalty = false, restarted = false;
  for (std::size_t h = 0; h < s.holes; ++h) restarted = restarted || play.restarts(h) > 0;
  for (std::size_t p = 0; p < n; ++p)
    for (std::size_t h = 0; h < s.holes; ++h) {
      received = received || s.players[p].received[h] > 0;
      const HoleCard& c = g.round(static_cast<int>(p)).card()[h];
      picked_up = picked_up || c.picked_up;
      conceded = conceded || c.conceded;
      penalty = penalty || c.penalties > 0;
    }
  std::string key = "SI the stroke index (the hole's rank by difficulty, where handicap strokes fall); putts in brackets";
  if (received) key = "* a stroke received (handicap); " + key;
  if (penalty) key += "; 1p a penalty stroke";
  if (picked_up) key += "; PU picked up";
  if (conceded) key += "; C a hole conceded, - one left unfinished: no score, in no total";
  if (restarted) key += "; R the hole was restarted from the menu (its first try not counted)";
  // Wrapped: with several marks the key runs past the card's 600 px.
  ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled));
  ImGui::TextWrapped("%s", key.c_str());
  ImGui::PopStyleColor();
  if (s.match) ImGui::Text("Match: %s", s.match->result.c_str());
  else if (final && s.holes > 0 && n > 1) {
    std::string names;
    for (int p : s.leaders) names += (names.empty() ? "" : ", ") + g.players()[static_cast<std::size_t>(p)].name;
    if (s.leaders.empty()) ImGui::TextUnformatted("No skins won: every hole carried");
    else ImGui::Text("%s: %s", s.leaders.size() > 1 ? "Tied" : "Winner", names.c_str());
  }
  ImGui::TextDisabled(final ? "N: a new round   Tab: next mode   Esc: menu (Q there quits)" : "Enter: next hole");
  ImGui::End();
}

}  // namespace sweetspot
