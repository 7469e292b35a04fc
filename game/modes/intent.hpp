// What a player asks a game mode to do, as plain data: the views turn key presses, clicks
// and panel edits into intents, the tests script them, and a mode's model applies them in
// `update(intents, now)`. Each intent carries the time it was asked for (s, on the mode's
// clock): a key's time is read when the key went down, not when a frame got round to it,
// so a meter click is judged to the millisecond at any frame rate.
#pragma once

#include <algorithm>
#include <string>
#include <vector>

namespace sweetspot {

enum class IntentKind : unsigned char {
  Swing,        ///< golf: start the meter / the next click; batting: swing at the pitch
  Cancel,       ///< Esc: drop what is in progress (a meter) with nothing counted
  Restart,      ///< the pause menu's "restart": the hole (golf), the session (batting), the shot (Lab)
  Continue,     ///< Enter: skip the flight, the next hole
  AimLeft,      ///< golf: aim a step left (`value` steps, 1 when 0)
  AimRight,
  ClubUp,       ///< golf: the next longer club
  ClubDown,
  CaddieClub,   ///< golf: the caddie's club for the distance
  CaddiePlays,  ///< golf: the caddie's bot plays this stroke
  Concede,      ///< golf, match play: give up the hole
  ReadGreen,    ///< golf, a putt: the caddie's read of its line and pace (again: hide it)
  Pitch,        ///< batting: call for the next pitch
  BatUp,        ///< batting: the bat's height a step up (BattingCage::kBatStep)
  BatDown,
  TogglePower,  ///< batting: power / contact swing
  ToggleSide,   ///< batting: right- / left-handed
  BotSwings,    ///< batting: the pro bot swings at this pitch
  ToggleLive,   ///< batting: batting practice / a live game against the league's pitcher
  ToggleTiming, ///< batting: the bat's height set by hand (Up/Down), or read for you (timing only)
  Replay,       ///< the last shot again from its start
  Edit,         ///< Lab: set parameter `param` to `value` (SI)
  Choose,       ///< Lab: set choice `param` to `text` (a scenario, club, bat, model)
  Save,         ///< Lab: write the current shot as scenario TOML to `text`
  NewRound,     ///< golf: from the final card, a new round (N; Enter, pressed to skip flights, keeps the card)
  TogglePace,   ///< batting: the next pitches' pace, standard -> easy -> pro -> standard (between pitches)
};

struct Intent {
  IntentKind kind = IntentKind::Swing;
  double time = 0.0;  ///< s on the mode's clock when it was asked for
  int param = 0;      ///< Edit / Choose: which parameter (the mode's own enum)
  double value = 0.0; ///< Edit: the value, SI
  std::string text;   ///< Choose / Save
};

using Intents = std::vector<Intent>;

/// The one way a model takes a frame's intents: in time order (a stable sort keeps the order
/// of two at the same time), the model advanced to each one's time before it is applied,
/// then to `now`.
template <class Advance, class Apply>
void apply_in_time_order(const Intents& intents, double now, Advance&& advance, Apply&& apply) {
  Intents ordered = intents;
  std::stable_sort(ordered.begin(), ordered.end(), [](const Intent& a, const Intent& b) { return a.time < b.time; });
  for (const Intent& in : ordered) {
    advance(in.time);
    apply(in);
  }
  advance(now);
}

}  // namespace sweetspot
