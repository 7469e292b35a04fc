// How a scenario's shot is shown: which world and meshes, where the club or bat was at
// impact. Shared by `sweetspot render SCENARIO`, `play` (window and headless) so every view
// of one shot draws the same scene.
#pragma once

#include <optional>
#include <string>

#include "game/render/render_command.hpp"
#include "game/render/shot_scene.hpp"
#include "game/scenario/scenario.hpp"

namespace sweetspot {

/// "driver_head" for woods (loft below 25°), "iron_head" for irons and wedges, "bat" for
/// baseball, "" for launch-only scenarios (nothing struck the ball on screen).
std::string impactor_mesh_for(const Scenario& s);

/// The club or bat at impact in its mesh frame, when the shot had one.
std::optional<ImpactorPlacement> impactor_placement(const ShotResult& r);

ShotSceneInput scene_input_for(const Scenario& s, const ShotResult& r);
RenderRequest render_request_for(const Scenario& s, const ShotResult& r);

}  // namespace sweetspot
