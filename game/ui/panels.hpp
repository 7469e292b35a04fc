// The Dear ImGui panels of the game window (DESIGN §7): Shot, Tuning, Launch monitor,
// Trajectory, Replay. Each returns true when the user changed something that needs the
// shot recomputed; edits go into UiState as scenario overrides (see ui_state.hpp).
#pragma once

#include <string>

#include "game/render/camera.hpp"
#include "game/ui/layout.hpp"
#include "game/ui/replay.hpp"
#include "game/ui/ui_state.hpp"
#include "game/core/shot_result.hpp"

namespace sweetspot {

/// What the panels show and edit in one frame.
struct PanelContext {
  const Assets& assets;
  UiState& state;
  const Scenario& scenario;       ///< the loaded scenario (after overrides)
  const ShotResult& result;       ///< its shot
  ReplayState& replay;
  CameraKind& camera;
  std::string& status;            ///< one line under the panels: last error or "saved FILE"
  std::string& save_path;         ///< Save box text
};

/// Draws the panels where `layout` puts them (layout.hpp: two columns, one sidebar, or
/// only a HUD). Returns true when the shot must be recomputed.
bool draw_panels(PanelContext& ctx, const PanelLayout& layout);

}  // namespace sweetspot
