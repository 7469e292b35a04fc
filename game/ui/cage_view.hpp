// The batting cage's view: pitches seen from behind the batter with the strike zone and the
// bat's height drawn, the call, the batted ball's flight, the spray chart and the session's
// numbers; keys become the BattingCage model's intents.
#pragma once

#include <memory>
#include <ostream>

#include "game/modes/baseball/cage.hpp"
#include "game/ui/mode_view.hpp"

namespace sweetspot {

struct CageViewOptions {
  bool exit_when_done = false;  ///< done() once `pitches` swings or takes have been called
  int pitches = 0;
};

/// Keys: P (or Space between pitches) a pitch, Space the swing, Up/Down the bat's height,
/// C power/contact, L the batter's side, B the pro swings.
Intents cage_intents(const std::vector<KeyPress>& keys);

/// What the window prints of the cage as it closes (however it was reached: --mode baseball
/// or Tab): the player's figures as the panel shows them, a live game's line, then every
/// swing as "swing: CALL  WORDS" (CALL the record's code: "single", "foul_tip", ...; WORDS
/// the call as the player was told it: "Strikeout on a foul tip"; a ball still in the air
/// says so).
void cage_report(const BattingCage& cage, std::ostream& out);

std::unique_ptr<ModeView> make_cage_view(const Assets& assets, std::unique_ptr<BattingCage> model, const CageViewOptions& o);

}  // namespace sweetspot
