// The Dear ImGui panels of the Lab (DESIGN §7): Shot, Tuning, Launch monitor, Trajectory,
// Replay. They read the LabModel and turn each change into an intent (an Edit of one
// ShotSpec field in SI, a Choose, a Save); the model runs the shot.
#pragma once

#include <string>

#include "game/modes/lab/lab_model.hpp"
#include "game/modes/replay.hpp"
#include "game/render/camera.hpp"
#include "game/ui/layout.hpp"

namespace sweetspot {

/// What the panels show and edit in one frame.
struct PanelContext {
  const Assets& assets;
  const LabModel& lab;
  Intents& out;                   ///< the frame's intents for the model
  double now;                     ///< s, the time the intents carry
  ReplayState& replay;            ///< the view's playback of the shot
  CameraKind& camera;
  std::string& save_path;         ///< Save box text
  std::string& note;              ///< a line from the panels themselves ("not saved: ... exists")
};

/// Draws the panels where `layout` puts them (layout.hpp: two columns, one sidebar, or
/// only a HUD). Returns true when it sent an intent that changes the shot.
bool draw_panels(PanelContext& ctx, const PanelLayout& layout);

}  // namespace sweetspot
