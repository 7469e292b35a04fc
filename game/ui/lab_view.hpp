// The Lab's view: the shot in 3-D with the orbit camera, the replay and the panels; Space
// runs the shot again, R replays it, 1–4 pick a camera, H hides the panels.
#pragma once

#include <memory>

#include "game/modes/lab/lab_model.hpp"
#include "game/ui/mode_view.hpp"

namespace sweetspot {

std::unique_ptr<ModeView> make_lab_view(const Assets& assets, std::unique_ptr<LabModel> model);

}  // namespace sweetspot
