#include "game/ui/cage_view.hpp"

#include <GLFW/glfw3.h>
#include <imgui.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <optional>
#include <ostream>
#include <string>
#include <string_view>
#include <utility>

#include "game/modes/replay.hpp"
#include "game/render/renderer.hpp"
#include "game/render/shot_scene.hpp"
#include "game/rules/baseball_game.hpp"
#include "game/ui/cage_people.hpp"
#include "game/ui/pitch_words.hpp"
#include "game/ui/two_lines.hpp"
#include "game/ui/wrapped_text.hpp"
#include "physics/units.hpp"

namespace sweetspot {

Intents cage_intents(const std::vector<KeyPress>& keys) {
  return intents_from_keys(keys, {{GLFW_KEY_SPACE, IntentKind::Swing},
                                  {GLFW_KEY_P, IntentKind::Pitch},
                                  {GLFW_KEY_UP, IntentKind::BatUp},
                                  {GLFW_KEY_DOWN, IntentKind::BatDown},
                                  {GLFW_KEY_C, IntentKind::TogglePower},
                                  {GLFW_KEY_L, IntentKind::ToggleSide},
                                  {GLFW_KEY_B, IntentKind::BotSwings},
                                  {GLFW_KEY_A, IntentKind::ToggleLive},
                                  {GLFW_KEY_T, IntentKind::ToggleTiming},
                                  {GLFW_KEY_E, IntentKind::TogglePace}});
}

namespace {

using Stage = BattingCage::Stage;

// px: the HUD panel's right edge, 450 px, or short of the pitcher in the image's middle in a
// narrow window (at 800 px a 450 px panel would hide his release).
float stats_panel_right(int w) { return std::min(450.0f, 0.42f * static_cast<float>(w)); }

// px: the panel's left edge. It stands on the side away from the batter (a right-handed
// batter stands left of the plate as the camera sees him, his head level with the panel's
// middle lines), with the spray chart below it; the call's banner takes the sky on the other side.
float stats_panel_left(bool batter_left, int w) {
  return batter_left ? 10.0f : static_cast<float>(w) - stats_panel_right(w);
}

// From behind the plate a little to the side away from the batter, so he stands at the
// left (right for a left-hander) of the view and the pitcher's release is clear of him.
Camera batter_view(bool batter_left) {
  const double away = batter_left ? -1.0 : 1.0;  // +z is away from a right-handed batter
  Camera c;
  // Looking a little down, so the whole zone and a low breaking ball's ring sit well inside
  // the frame while the pitcher's release stays in it.
  c.eye = Vec3(-3.2, 1.6, 0.25 * away);
  c.target = Vec3(10.0, 0.6, 0.0);
  c.fov_y = deg_to_rad(40.0);
  return c;
}

void draw_zone(const BattingCage& c, const Camera& cam, int w, int h, bool crossed) {
  ImDrawList* dl = ImGui::GetBackgroundDrawList();
  const auto pt = [&](double y, double z) -> std::optional<ImVec2> {
    const auto p = cam.project(Vec3(0.0, y, z), w, h);
    if (!p) return std::nullopt;
    return ImVec2(static_cast<float>((*p)(0)), static_cast<float>((*p)(1)));
  };
  const double lo = BattingCage::kZoneLow, hi = BattingCage::kZoneHigh, half = BattingCage::kPlateHalf;
  const auto a = pt(hi, -half), b = pt(hi, half), d = pt(lo, half), e = pt(lo, -half);
  if (a && b && d && e) dl->AddQuad(*a, *b, *d, *e, IM_COL32(255, 255, 255, 200), 2.0f);
  // Where the pitch crossed the front of the plate, once it has (a taken pitch or a miss;
  // `crossed`: the ball shown is there): the call's evidence, green in the zone, red
  // outside, as big as the ball.
  if (c.stage() == Stage::Called && !c.batted() && crossed) {
    const Vec3& at = c.pitch().plate;
    const double r = c.ball_radius();
    const auto centre = pt(at.y(), at.z()), edge = pt(at.y(), at.z() + r);
    if (centre && edge) {
      const float rad = std::max(4.0f, std::abs(edge->x - centre->x));
      const ImU32 col = StrikeZone::contains(at, r) ? IM_COL32(90, 230, 120, 255) : IM_COL32(240, 80, 70, 255);
      dl->AddCircle(*centre, rad, col, 20, 2.5f);
    }
  }
  // The bat's height: where the swing will meet the ball (timing only: wherever the pitch is,
  // so no line).
  if (c.timing_only()) return;
  const auto l = pt(c.bat_height(), -half - 0.25), r = pt(c.bat_height(), half + 0.25);
  if (l && r) dl->AddLine(*l, *r, c.power() ? IM_COL32(255, 170, 40, 230) : IM_COL32(80, 200, 255, 230), 3.0f);
}

// The spray chart's dots by outcome, with the key's words; any other ball in play is an out.
struct SprayKey {
  BattedOutcome outcome;
  ImU32 colour;
  const char* word;
};
constexpr std::array<SprayKey, 5> kSprayKey{{{BattedOutcome::HomeRun, IM_COL32(220, 40, 40, 255), "HR"},
                                             {BattedOutcome::Triple, IM_COL32(250, 130, 0, 255), "3B"},
                                             {BattedOutcome::Double, IM_COL32(235, 200, 100, 255), "2B"},
                                             {BattedOutcome::Single, IM_COL32(40, 160, 140, 255), "1B"},
                                             {BattedOutcome::Foul, IM_COL32(140, 200, 230, 255), "foul"}}};
constexpr ImU32 kSprayOut = IM_COL32(150, 150, 150, 255);

// The HUD panel at the top left; returns its bottom edge (px), where the call goes below it.
// `all_keys`: every key the cage takes, four lines; else the few a pitch needs, in one.
// `pitch_by`: the pitch has reached the plate (its shape is then told). `chart`: the spray
// chart below the panel (not while the pause menu stands there); `chart_x` gets its left and
// right edges (px) when it is drawn.
float draw_stats(const BattingCage& c, int w, int h, bool all_keys, bool pitch_by, bool chart, std::optional<std::pair<float, float>>* chart_x) {
  ImGui::SetNextWindowPos(ImVec2(stats_panel_left(c.left_handed(), w), 10), ImGuiCond_Always);
  ImGui::SetNextWindowSize(ImVec2(stats_panel_right(w) - 10.0f, 0), ImGuiCond_Always);
  // Named for what is played in it (A switches): one window either way (the id after ###).
  ImGui::Begin(c.live() ? "Live game###cage_stats" : "Batting practice###cage_stats", nullptr, ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse);
  const BattingCage::Figures fig = c.figures();
  if (c.live()) {
    const BattingCage::AtBats& a = c.at_bats();
    if (const LiveInning::Board* b = c.board()) {
      // The scoreboard: the inning, outs, runners and count; the line score; the last play's
      // part for the runners (or the inning's line once the side is retired).
      if (b->final)
        ImGui::TextWrapped("%s. P: a new game", b->final_line.c_str());
      else if (b->side_retired)
        ImGui::TextWrapped("End of the %s: you bat in the top of the %s", ordinal(b->inning).c_str(), ordinal(b->inning + 1).c_str());
      else
        ImGui::TextWrapped("Top of the %s, %d %s, %s, count %d-%d", ordinal(b->inning).c_str(), b->outs, b->outs == 1 ? "out" : "outs",
                    runners_text(b->bases).c_str(), c.count().balls, c.count().strikes);
      // The line score as a scoreboard shows it: an inning a column, its number over each
      // side's runs (a bottom half not played blank, an "x" where the home side did not need
      // to bat), then runs and hits (the HUD's font is monospaced, so the columns line up);
      // past nine innings the last nine, as a scoreboard's extra-inning columns scroll.
      std::string top = "       ", ours = "You    ", theirs = "League ";
      char cell[32];
      constexpr std::size_t kColumns = 9;
      const std::size_t n = b->runs_by_inning.size();
      for (std::size_t i = n > kColumns ? n - kColumns : 0; i < n; ++i) {
        std::snprintf(cell, sizeof cell, "%3zu", i + 1);
        top += cell;
        std::snprintf(cell, sizeof cell, "%3d", b->runs_by_inning[i]);
        ours += cell;
        if (i < b->their_runs_by_inning.size()) std::snprintf(cell, sizeof cell, "%3d", b->their_runs_by_inning[i]);
        else std::snprintf(cell, sizeof cell, "%3s", b->final ? "x" : "");
        theirs += cell;
      }
      std::snprintf(cell, sizeof cell, "%5s%4s", "R", "H");
      top += cell;
      std::snprintf(cell, sizeof cell, "%5d%4d", b->runs(), b->hits);
      ours += cell;
      std::snprintf(cell, sizeof cell, "%5d%4d", b->their_runs(), b->their_hits);
      theirs += cell;
      ImGui::TextUnformatted(top.c_str());
      ImGui::TextUnformatted(ours.c_str());
      ImGui::TextUnformatted(theirs.c_str());
      if (!b->note.empty()) ImGui::TextWrapped("%s%s", b->side_retired ? "" : "Last play: ", b->note.c_str());
      if (!b->their_half.empty()) ImGui::TextWrapped("%s", b->their_half.c_str());
    }
    const int in_play = a.outs - a.strikeouts;
    ImGui::TextWrapped("PA %d: %d H (%d HR), %d K, %d BB, %d HBP, %d %s in play", a.pa, a.hits, a.home_runs, a.strikeouts, a.walks,
                a.hit_by_pitch, in_play, in_play == 1 ? "out" : "outs");
  } else {
    ImGui::TextWrapped("Batting practice");
  }
  if (c.stage() == Stage::Ready) {
    // The pace it comes at, so a player knows what --difficulty changed (easy 30 %, standard
    // 50 %, pro real time: BattingCage::time_scale()).
    if (c.next_time_scale() >= 1.0) ImGui::TextWrapped("%s", "Pitch: P or Space calls for one, at real speed");
    else ImGui::TextWrapped("Pitch: P or Space calls for one, at %.0f %% of real speed", 100.0 * c.next_time_scale());
    if (!c.timing_only() && c.swings().empty()) ImGui::TextWrapped("%s", "New to it? T: just time the swing, the bat finds the height");
  } else if (c.stage() == Stage::Pitching || (!c.batted() && !pitch_by)) {
    // (A pitch swung through early is still on its way.) In practice the pitch is called as
    // a coach feeding a machine would; in a game the pitcher does not tell the hitter what is
    // coming: named once it is by.
    if (c.live())
      ImGui::TextWrapped("Pitch: from the %s-hander, on its way (named once it is by)", c.call().left_handed ? "left" : "right");
    else ImGui::TextWrapped("Pitch: %s %.0f mph", c.call().type.type.c_str(), mps_to_mph(c.call().type.speed));
  } else {
    // Once it has gone by, its shape as Statcast tells it: the run toward the pitcher's arm or
    // glove side and the rise or drop against a spinless ball (induced vertical break).
    const PitchMovement& m = c.movement();
    const bool arm_side = (m.horizontal_break < 0.0) != c.call().left_handed;
    // Said against the spinless ball ("2 in higher"): a slider's "2 in rise" read as a pitch
    // that climbs, where it drops all the way, only less than gravity alone would drop it.
    const double run_in = 12.0 * std::abs(m_to_ft(m.horizontal_break));
    ImGui::TextWrapped("Pitch: %s%s %.0f mph, %.0f in %s, %.0f in %s than a spinless ball", c.call().left_handed ? "left-hander's " : "",
                       c.call().type.type.c_str(), mps_to_mph(c.call().type.speed), run_in, arm_side ? "arm side" : "glove side",
                       12.0 * std::abs(m_to_ft(m.induced_vertical_break)), m.induced_vertical_break >= 0.0 ? "higher" : "lower");
    // The same in the batter's words: where it crossed for him and which way it moved.
    const bool same_hand = c.call().left_handed == c.left_handed();
    ImGui::TextWrapped("%s", pitch_for_batter(c.pitch().plate, c.ball_radius(), c.left_handed(), arm_side == same_hand, run_in).c_str());
  }
  // Three misses in a row at a pace quicker than the easiest, between pitches: where a
  // slower pitch is.
  const bool between = c.stage() == Stage::Ready || (c.stage() == Stage::Called && c.told());
  if (between && c.misses_in_a_row() >= 3 && c.next_time_scale() > BattingCage::kEasyPitchTimeScale)
    ImGui::TextWrapped("%s", "Missing them? E: slower pitches");
  ImGui::TextWrapped("Swing: %s, %s-handed, %s", c.power() ? "power" : "contact", c.left_handed() ? "left" : "right",
              c.timing_only() ? "timing only" : "bat height by hand");
  if (!all_keys) {
    // After the first few swings the keys a pitch needs, in one line (K: the rest).
    disabled_wrapped(c.timing_only() ? "P pitch  Space swing  B the pro  K/F1 keys" : "P pitch  Space swing  Up/Down bat  K/F1 keys");
  } else {
    if (c.timing_only()) disabled_wrapped("P: pitch  Space: swing  T: set the bat's height yourself");
    else disabled_wrapped("P: pitch  Space: swing  Up/Down: bat height  T: timing only");
    disabled_wrapped("C: power/contact  L: batter's side  E: pitch pace");
    disabled_wrapped("B: the pro swings  A: live game / batting practice");
    disabled_wrapped("H: hide this panel  Esc: pause  Tab: next mode  K/F1: fewer");
  }
  ImGui::Separator();
  // The swing and the contact count as soon as they happen (the call above says "off the
  // bat"); fair or foul and how far only once the play is called.
  const int n = fig.swings, pro = fig.by_pro, fair = fig.fair;
  ImGui::TextWrapped("Your swings %d, contact %d, fair %d, home runs %d", n, fig.contact, fair, fig.home_runs);
  if (pro > 0) disabled_wrapped("(and %d by the pro, B: not in your figures)", pro);
  if (!c.swings().empty()) {
    // Statcast's bat tracking: the last swing (the bat's own figures, known at contact), and
    // the swings' squared-up and blast counts (the same swings as the line above).
    const SwingRecord& last = c.swings().back();
    const BatTracking& t = last.result.tracking;
    int squared = 0, blasts = 0;
    for (std::size_t i = 0; i < c.swings().size(); ++i) {
      if (c.swings()[i].by_pro) continue;
      squared += c.swings()[i].result.tracking.is_squared_up;
      blasts += c.swings()[i].result.tracking.blast;
    }
    // After a pitch taken, these are the swing before it: said so, not read as the take's.
    const bool taken = !c.last().swung;
    const char* whose = taken ? (last.by_pro ? "Pro's last swing: bat" : "Last swing: bat") : last.by_pro ? "Pro's bat" : "Bat";
    // The attack angle and direction are the bat's where it meets the ball; a miss meets it
    // nowhere (an early bat has turned past 90 deg of pull by the time the ball arrives), so a
    // miss shows what every swing has: its speed and length.
    const bool met = last.result.contact;
    if (met)
      // Rounded before printing: no "-0 deg" for an attack a hair below level.
      // Wrapped: "Pro's last swing: bat ... 7.3 ft swing" runs past the panel's width.
      ImGui::TextWrapped("%s %.1f mph, attack %.0f deg, %s %.0f deg, %.1f ft swing", whose, mps_to_mph(t.bat_speed_mps),
                  std::round(t.attack_angle_deg) + 0.0, t.attack_direction_deg >= 0.0 ? "oppo" : "pull",
                  std::abs(t.attack_direction_deg), m_to_ft(t.swing_length_m));
    else
      ImGui::TextWrapped("%s %.1f mph, %.1f ft swing (a miss)", whose, mps_to_mph(t.bat_speed_mps), m_to_ft(t.swing_length_m));
    // Squared up is Statcast's 80 % line: the last swing's share, rounded down so that 79.7 %
    // does not read as 80 % beside a count that (rightly) leaves it out.
    if (met)
      // Held at 100 %: the best exit speed is the most a swing of that speed can give.
      ImGui::TextWrapped("%s: %.0f %% of its best exit speed", last.by_pro ? (taken ? "The pro's last swing" : "The pro's swing") : "Last swing",
                  std::min(100.0, std::floor(100.0 * t.squared_up)));
    if (n > 0) ImGui::TextWrapped("Squared up (80 %%+) %d of %d swings, blasts %d", squared, n, blasts);
  }
  if (fair > 0) {
    ImGui::TextWrapped("Fair balls: exit velocity %.1f mph, launch %.1f deg", mps_to_mph(fig.mean_exit_speed), rad_to_deg(fig.mean_launch));
    // The carry (Statcast's hit distance: to the first bounce or the glove), said as such:
    // a grounder session's "longest 4 ft" is its longest carry.
    ImGui::TextWrapped("Hard-hit %.0f %%, longest carry %.0f ft", 100.0 * fig.hard_hit / fair, m_to_ft(fig.longest));
  }
  const float bottom = ImGui::GetWindowPos().y + ImGui::GetWindowSize().y;
  ImGui::End();
  // No chart over the pause menu, nor over the panel's own last lines where the window is
  // too short for it below them (K shortens the panel and makes the room).
  constexpr float kLeastChart = 120.0f;  // px: the title, two lines of key and the infield
  if (!chart || static_cast<float>(h) - 36.0f - bottom - 8.0f < kLeastChart) return bottom;

  // The spray chart, bottom corner away from the batter (a right-handed batter stands left of
  // the plate as the camera sees him): home plate at the bottom, fair ground to ~150 m (490 ft)
  // down either line and ~200 m up the middle, so every fair ball in this park shows.
  // Below the panel on its side: smaller in a short window rather than over the panel's lines.
  const float size = std::min(220.0f, static_cast<float>(h) - 36.0f - bottom - 8.0f);
  const float y0 = static_cast<float>(h) - size - 36.0f;
  const float x0 = c.left_handed() ? 12.0f : static_cast<float>(w) - size - 12.0f;
  *chart_x = std::pair{x0, x0 + size};
  ImDrawList* dl = ImGui::GetForegroundDrawList();
  // Opaque and framed: the field's own foul lines behind it must not read as the chart's.
  dl->AddRectFilled(ImVec2(x0, y0), ImVec2(x0 + size, y0 + size), IM_COL32(40, 90, 45, 255), 6.0f);
  dl->AddRect(ImVec2(x0, y0), ImVec2(x0 + size, y0 + size), IM_COL32(15, 30, 15, 255), 6.0f, 0, 2.0f);
  const float scale = (size / 2.0f - 6.0f) / 106.0f;  // px per m: 106 m across each side, 150 m down a line
  const ImVec2 home(x0 + size / 2, y0 + size - 8.0f);
  const auto px = [&](const Vec3& p) { return ImVec2(home.x + static_cast<float>(p.z()) * scale, home.y - static_cast<float>(p.x()) * scale); };
  // Everything inside the panel: the foul lines run out past its sides, a long ball past its top.
  dl->PushClipRect(ImVec2(x0, y0), ImVec2(x0 + size, y0 + size), true);
  dl->AddLine(home, px(Vec3(130, 0, 130)), IM_COL32(240, 240, 240, 255));
  dl->AddLine(home, px(Vec3(130, 0, -130)), IM_COL32(240, 240, 240, 255));
  // The infield's 90 ft square (27.43 m a side, MLB Rule 2.01): a grounder fielded there
  // reads as an infield ball, not a dot at home plate.
  constexpr double kBaseLine = 27.43 / 1.41421356237;  // m along x and z from home to first
  dl->AddQuad(home, px(Vec3(kBaseLine, 0, kBaseLine)), px(Vec3(2.0 * kBaseLine, 0, 0)), px(Vec3(kBaseLine, 0, -kBaseLine)),
              IM_COL32(190, 150, 100, 255), 1.5f);
  // A live game's runners: a base with a man on it filled.
  if (const LiveInning::Board* b = c.board(); b && !b->side_retired)
    for (int base = 1; base <= 3; ++base) {
      const ImVec2 at = px(base_position(base));
      const bool on = b->bases[static_cast<std::size_t>(base - 1)] >= 0;
      const ImVec2 q[4] = {ImVec2(at.x, at.y - 5), ImVec2(at.x + 5, at.y), ImVec2(at.x, at.y + 5), ImVec2(at.x - 5, at.y)};
      if (on) dl->AddConvexPolyFilled(q, 4, IM_COL32(250, 220, 60, 255));
      else dl->AddPolyline(q, 4, IM_COL32(240, 240, 240, 255), ImDrawFlags_Closed, 1.0f);
    }
  bool pro_shown = false;
  for (std::size_t i = 0; i < c.swings_told(); ++i) {
    const SwingRecord& s = c.swings()[i];
    if (!s.result.contact) continue;
    const FlightSummary& f = s.result.shot.trajectory.summary;
    // Where it came down, or for a ball on the ground where a fielder picked it up or caught
    // it, or where a foul was called (the physics' roll past him, or up the line, was never
    // played).
    const FieldingPlay& play = s.result.play;
    const bool in_air = f.carry_m > 40.0 || s.result.outcome == BattedOutcome::HomeRun;
    const Vec3 p = in_air ? f.landing_position : play_rest_position(s.result.shot.trajectory, play);
    const auto key = std::find_if(kSprayKey.begin(), kSprayKey.end(), [&](const SprayKey& k) { return k.outcome == s.result.outcome; });
    const ImU32 colour = key != kSprayKey.end() ? key->colour : kSprayOut;
    // The pro's balls are not the player's figures: a ring, so his own dots stay his.
    if (s.by_pro) dl->AddCircle(px(p), 4.0f, colour, 0, 1.5f);
    else dl->AddCircleFilled(px(p), 4.0f, colour);
    pro_shown = pro_shown || s.by_pro;
  }
  dl->PopClipRect();
  dl->AddText(ImVec2(x0 + 6, y0 + 4), IM_COL32(255, 255, 255, 255), "spray chart");
  // The key to the dots, under the title: each colour with its scorer's abbreviation, on as
  // many lines as the chart's width needs (a small window's chart is narrower than the key).
  float kx = x0 + 8.0f;
  float ky = y0 + 8.0f + ImGui::GetTextLineHeight();
  const auto key_entry = [&](ImU32 colour, const char* word) {
    const float width = 9.0f + ImGui::CalcTextSize(word).x;
    if (kx > x0 + 8.0f && kx + width > x0 + size - 4.0f) {
      kx = x0 + 8.0f;
      ky += ImGui::GetTextLineHeight() + 2.0f;
    }
    dl->AddCircleFilled(ImVec2(kx + 3.0f, ky + 0.5f * ImGui::GetTextLineHeight()), 4.0f, colour);
    dl->AddText(ImVec2(kx + 9.0f, ky), IM_COL32(255, 255, 255, 255), word);
    kx += width + 5.0f;
  };
  for (const SprayKey& k : kSprayKey) key_entry(k.colour, k.word);
  key_entry(kSprayOut, "out");
  if (pro_shown) {
    const float ry = ky + ImGui::GetTextLineHeight() + 2.0f;
    dl->AddCircle(ImVec2(x0 + 11.0f, ry + 0.5f * ImGui::GetTextLineHeight()), 4.0f, IM_COL32(255, 255, 255, 255), 0, 1.5f);
    dl->AddText(ImVec2(x0 + 17.0f, ry), IM_COL32(255, 255, 255, 255), "the pro's");
  }
  return bottom;
}

// What a restart loses of a live game: the game so far (its plate appearances), or the one
// under way (a 2-0 count); nothing before its first pitch.
std::string live_game_loses(int pa, const Count& k, bool swung) {
  if (pa > 0) return "the live game so far (" + std::to_string(pa) + (pa == 1 ? " plate appearance)" : " plate appearances)");
  if (k.balls > 0 || k.strikes > 0 || swung)
    return "the live game's first plate appearance (" + std::to_string(k.balls) + "-" + std::to_string(k.strikes) + ")";
  return {};
}

// And of batting practice: its swings, the pro's among them.
std::string practice_loses(const std::vector<SwingRecord>& swings, const std::string& whose) {
  const std::size_t n = swings.size();
  if (n == 0) return {};
  std::size_t pro = 0;
  for (const SwingRecord& s : swings) pro += s.by_pro;
  return whose + std::to_string(n) + (n == 1 ? " swing" : " swings") +
         (pro > 0 ? " (" + std::to_string(pro) + " by the pro)" : std::string());
}

class CageView final : public ModeView {
 public:
  const ShotScene* clip_scene() const override { return scene_.get(); }
  CageView(const Assets& assets, std::unique_ptr<BattingCage> m, const CageViewOptions& o) : cage_(std::move(m)), options_(o) {
    ShotSceneInput in;
    in.assets = &assets;
    in.world = assets.world("ballpark");
    in.distance_unit = "ft";
    in.ball_radius = assets.equipment().ball("mlb").radius;
    scene_ = std::make_unique<ShotScene>(in);
  }
  // As the panel is titled: what is being played in the cage.
  const char* title() const override { return cage_->live() ? "Baseball: live game" : "Baseball: batting practice"; }
  AmbienceSpec ambience() const override { return {Ambience::Ballpark, 0.0}; }
  const char* restart_label() const override { return "Restart session"; }
  std::string restart_loses() const override {
    // A restart clears both records (the one on and the one A keeps for the way back).
    const BattingCage& c = *cage_;
    const std::string on = c.live() ? live_game_loses(c.game_pa(), c.count(), !c.swings().empty())
                                    : practice_loses(c.swings(), "this session's ");
    const std::string kept = c.live() ? practice_loses(c.other_swings(), "batting practice's ")
                                      : live_game_loses(c.other_game_pa(), Count{}, false);
    if (on.empty() || kept.empty()) return on + kept;
    return on + " and " + kept;
  }
  void send(const Intent& in) override { cage_->update({in}, in.time); }
  bool done() const override { return options_.exit_when_done && done_frames_ >= 30; }
  void report(std::ostream& out) const override { cage_report(*cage_, out); }
  void frame(const ViewInput& in, Renderer& renderer) override {
    const BattingCage& c = *cage_;
    const std::size_t before = c.swings().size();
    // As last drawn: a restart from the pause menu reaches the model through send().
    const Stage stage_before = drawn_stage_;
    cage_->update(cage_intents(in.keys), in.now);
    // H hides the panel and the spray chart (and brings them back), as in the Lab: the view
    // whole, for a screenshot or a clip.
    for (const KeyPress& k : in.keys)
      if (k.key == GLFW_KEY_H) panels_hidden_ = !panels_hidden_;
      else if (k.key == GLFW_KEY_K || k.key == GLFW_KEY_F1) all_keys_ = !all_keys();  // F1: where a newcomer looks for help
    drawn_stage_ = c.stage();
    // The scene holds the pitch while it flies and the batted ball after contact.
    if (c.stage() == Stage::Pitching && stage_before != Stage::Pitching) {
      scene_->set_shot(c.pitch().trajectory, std::nullopt);
      scene_->set_carry_label(true);
      scene_->set_carry_words("");
      scene_->set_rest_words("");
    }
    // A fresh session (restart, or A between batting practice and live at-bats): no old trace.
    if (c.stage() == Stage::Ready && stage_before != Stage::Ready) scene_->set_shot(ShotTrajectory{}, std::nullopt);
    if (c.swings().size() != before && c.last().result.contact) {
      scene_->set_shot(c.played(), std::nullopt);
      // A ground ball's distance is where it was fielded (the call's, the rest label's). A
      // ball that came down and was picked up has two distances, each said for what it is.
      const FieldingPlay& play = c.last().result.play;
      scene_->set_carry_label(batted_ball_type(c.last().result.shot.launch.vertical_angle) != BattedBallType::GroundBall);
      scene_->set_carry_words("landed");
      scene_->set_rest_words(play.fielder >= 0 && !play.caught && !play.foul ? "fielded" : "");
      ImpactSoundInput crack;
      crack.contact_time = c.last().result.contact_time;
      crack.normal_impulse = c.last().result.normal_impulse;
      crack.ring = ring_for(BattingCage::kBat, "baseball");
      sound_strike(crack);
    }
    const int w = in.width, h = in.height;
    // Whether the pitch has reached the plate: a missed one flies on after the swing.
    const bool pitch_by = c.pitch_clock(in.now) >= c.pitch().flight_time;
    if (w > 0 && h > 0) {
      fit_renderer(renderer, w, h, in.render_scale);
      const bool batted = c.batted();
      const double flight_end = duration(c.played());
      // The ball holds at the plate, or where the batted ball stopped, while the people go on
      // (their clock: cage_people).
      // A missed pitch flies on to the plate (a swing through early does not stop it there).
      const bool pitch_in_air = c.stage() == Stage::Pitching || (c.stage() == Stage::Called && !batted);
      const double t = pitch_in_air ? std::min(c.pitch_clock(in.now), c.pitch().flight_time)
                       : batted ? (c.stage() == Stage::Batted ? std::clamp(in.now - c.batted_at(), 0.0, flight_end) : flight_end)
                                : c.pitch().flight_time;
      // The batted ball framed below the HUD panel and the call under it (last frame's
      // extent), so its apex never flies behind them.
      const FrameWindow below_hud{0.0, std::clamp((hud_bottom_ + 8.0) / h, 0.0, 0.5), 1.0, 1.0};
      // A ball that goes back over the plate (a foul to the screen) is seen from the side: from
      // behind the plate its climb toward the eye reads as a deep fly to centre field.
      const auto& flown = c.played().samples;
      const bool back_over_plate = batted && !flown.empty() && flown.back().position.x() < 0.0;
      const Camera cam = !batted ? batter_view(c.left_handed())
                         : back_over_plate ? scene_->camera(CameraKind::Side, t, w, h, below_hud)
                                           : scene_->camera(CameraKind::Behind, t, w, h, below_hud);
      scene_->set_people(cage_people(c, in.now));
      const bool moving = c.stage() == Stage::Pitching || batted;
      renderer.draw(scene_->build(cam, moving ? cage_scene_time(c, in.now) : t, w, h), cam);
      renderer.blit_to(0, w, h);
      if (!batted) draw_zone(c, cam, w, h, pitch_by);
      // The pitcher far off is a few pixels tall: his wind-up is told over the infield, filling
      // to the release, and gone as the ball leaves his hand (the cue to start reading it).
      if (const double clock = c.pitch_clock(in.now); c.stage() == Stage::Pitching && clock < 0.0) {
        const float cx = 0.5f * static_cast<float>(w), y = 0.52f * static_cast<float>(h);
        const float bottom = draw_banner("wind-up", cx, y, 1.2f);
        const float half = 60.0f, fill = static_cast<float>(std::clamp(1.0 + clock / kWindupTime, 0.0, 1.0));
        ImDrawList* dl = ImGui::GetForegroundDrawList();
        dl->AddRectFilled(ImVec2(cx - half, bottom + 4.0f), ImVec2(cx + half, bottom + 10.0f), IM_COL32(0, 0, 0, 170), 2.0f);
        dl->AddRectFilled(ImVec2(cx - half, bottom + 4.0f), ImVec2(cx - half + 2.0f * half * fill, bottom + 10.0f),
                          IM_COL32(255, 220, 90, 230), 2.0f);
      }
    }
    float panel_bottom = 0.0f;
    std::optional<std::pair<float, float>> chart_x;  // the spray chart's left and right edges, if drawn
    view_height_ = h;
    if (!panels_hidden_) {
      panel_bottom = draw_stats(c, w, h, all_keys(), pitch_by, !in.paused, &chart_x);
    } else {
      // One line says how to bring the panel back.
      ImGui::SetNextWindowPos(ImVec2(stats_panel_left(c.left_handed(), w), 10), ImGuiCond_Always);
      ImGui::Begin("cage hidden", nullptr, ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_AlwaysAutoResize);
      ImGui::TextDisabled("H: the panel");
      panel_bottom = ImGui::GetWindowPos().y + ImGui::GetWindowSize().y;
      ImGui::End();
    }
    hud_bottom_ = panel_bottom;
    if (!c.call_text().empty()) {
      // The call in large type, always in the sky beside the HUD panel (clear of the
      // outfield wall's distance signs and the pitcher), where the eye learns to look: on one
      // line, else cut in two at a clause break, in smaller type as long calls need; below
      // the panel only in a window too narrow for even that.
      // The free sky beside the panel: right of it for a left-handed batter, left of it else.
      const float panel_w = stats_panel_right(w) - 10.0f;
      const float free_from = c.left_handed() ? stats_panel_right(w) + 16.0f : 0.0f;
      const float free_to = c.left_handed() ? static_cast<float>(w) : static_cast<float>(w) - panel_w - 26.0f;
      const float room = free_to - free_from - 40.0f;
      const std::string& call = c.call_text();
      auto lines = std::pair<std::string, std::string>{call, std::string()};
      bool beside = false;
      float scale = 1.6f;
      for (const float try_scale : {1.6f, 1.4f, 1.2f}) {
        scale = try_scale;
        const auto width = [&](std::string_view t) { return banner_text_width(t, scale); };
        lines = {call, std::string()};
        if (width(call) > room) lines = split_in_two_lines(call, width);
        beside = std::max(width(lines.first), width(lines.second)) <= room;
        if (beside) break;
      }
      // Below the panel, the call keeps off the spray chart there: it takes the width beside it.
      float below_from = 0.0f, below_to = static_cast<float>(w);
      if (!beside && chart_x) {
        if (c.left_handed()) below_from = chart_x->second + 8.0f;
        else below_to = chart_x->first - 8.0f;
        for (const float try_scale : {1.6f, 1.4f, 1.2f, 1.0f}) {
          scale = try_scale;
          const auto two = split_in_two_lines(call, [&](std::string_view t) { return banner_text_width(t, scale); });
          if (std::max(banner_text_width(two.first, scale), banner_text_width(two.second, scale)) <= below_to - below_from - 40.0f) break;
        }
      }
      if (!beside) lines = split_in_two_lines(call, [&](std::string_view t) { return banner_text_width(t, scale); });
      const float centre = beside ? 0.5f * (free_from + free_to) : 0.5f * (below_from + below_to);
      const float bottom = draw_banner(lines.first.c_str(), centre, beside ? 22.0f : panel_bottom + 14.0f, scale, lines.second.c_str());
      hud_bottom_ = std::max(hud_bottom_, static_cast<double>(bottom));
    }
    if (options_.pitches > 0 && c.pitches_done() >= options_.pitches && c.stage() == Stage::Called && c.told())
      ++done_frames_;
  }

 private:
  std::unique_ptr<BattingCage> cage_;
  CageViewOptions options_;
  std::unique_ptr<ShotScene> scene_;
  int done_frames_ = 0;
  bool panels_hidden_ = false;  ///< H: the HUD panel and the spray chart out of the way
  /// Every key for the first few swings (in a window kAllKeysMinHeight tall), then the few a
  /// pitch needs; K switches (held on).
  std::optional<bool> all_keys_;
  static constexpr std::size_t kSwingsWithAllKeys = 5;
  int view_height_ = kAllKeysMinHeight;
  bool all_keys() const {
    return all_keys_.value_or(cage_->swings().size() < kSwingsWithAllKeys && view_height_ >= kAllKeysMinHeight);
  }
  double hud_bottom_ = 0.0;  ///< px, the lowest the HUD panel and the call reached last frame
  Stage drawn_stage_ = Stage::Ready;  ///< the model's stage the last frame drew
};

}  // namespace

void cage_report(const BattingCage& c, std::ostream& out) {
  const BattingCage::Figures f = c.figures();
  char line[200];
  std::snprintf(line, sizeof line, "baseball: %d %s, contact %d, fair %d, home runs %d", f.swings, f.swings == 1 ? "swing" : "swings",
                f.contact, f.fair, f.home_runs);
  out << line;
  if (f.by_pro > 0) out << " (and " << f.by_pro << " by the pro)";
  out << "\n";
  if (f.fair > 0) {
    std::snprintf(line, sizeof line, "fair balls: exit velocity %.1f mph, launch %.1f deg, hard-hit %.0f %%, longest carry %.0f ft",
                  mps_to_mph(f.mean_exit_speed), rad_to_deg(f.mean_launch), 100.0 * f.hard_hit / f.fair, m_to_ft(f.longest));
    out << line << "\n";
  }
  // Each live game finished before the one on now, by its final line.
  for (const std::string& final_line : c.finished_games()) out << "live game finished: " << final_line << "\n";
  if (c.live()) {
    const BattingCage::AtBats& a = c.at_bats();
    std::snprintf(line, sizeof line, "live game: PA %d: %d H (%d HR), %d K, %d BB, %d HBP against a %s-hander", a.pa, a.hits,
                  a.home_runs, a.strikeouts, a.walks, a.hit_by_pitch, c.pitcher_left() ? "left" : "right");
    out << line;
    if (const LiveInning::Board* b = c.board()) {
      // Where the game stands, as the scoreboard says it: a side retired is the inning's end.
      if (b->final) out << "; runs " << b->runs() << " (by inning:";
      else if (b->side_retired) out << "; end of the " << ordinal(b->inning) << ", runs " << b->runs() << " (by inning:";
      else
        out << "; top of the " << ordinal(b->inning) << ", " << b->outs << (b->outs == 1 ? " out" : " outs") << ", runs " << b->runs()
            << " (by inning:";
      for (const int r : b->runs_by_inning) out << " " << r;
      out << "), League " << b->their_runs() << " (by inning:";
      for (const int r : b->their_runs_by_inning) out << " " << r;
      out << ")";
      if (b->final) out << "; " << b->final_line;
    }
    out << "\n";
  }
  // Every swing the figures count; one whose ball was still in the air has not been called.
  for (std::size_t i = 0; i < c.swings().size(); ++i) {
    const SwingRecord& s = c.swings()[i];
    out << "swing: " << s.call_text;
    if (i >= c.swings_told()) out << "  (in the air as the window closed)";
    else if (!s.said.empty()) out << "  " << s.said;
    out << "\n";
  }
  // The record A left, kept: its figures and its swings, named for what they were.
  if (const auto o = c.other_figures()) {
    std::snprintf(line, sizeof line, "%s, kept: %d %s, contact %d, fair %d, home runs %d", c.live() ? "batting practice" : "live game",
                  o->swings, o->swings == 1 ? "swing" : "swings", o->contact, o->fair, o->home_runs);
    out << line;
    if (o->by_pro > 0) out << " (and " << o->by_pro << " by the pro)";
    out << "\n";
    for (const SwingRecord& s : c.other_swings())
      out << (c.live() ? "practice swing: " : "game swing: ") << s.call_text << (s.said.empty() ? "" : "  " + s.said) << "\n";
  }
}

std::unique_ptr<ModeView> make_cage_view(const Assets& assets, std::unique_ptr<BattingCage> model, const CageViewOptions& o) {
  return std::make_unique<CageView>(assets, std::move(model), o);
}

}  // namespace sweetspot
