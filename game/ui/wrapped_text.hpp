// Text helpers for the HUD panels that narrow with the window: every line wraps at the
// panel's edge rather than being cut there.
#pragma once

#include <imgui.h>

namespace sweetspot {

/// ImGui::TextDisabled that wraps at the panel's edge (a key line in a narrow panel).
void disabled_wrapped(const char* fmt, ...) IM_FMTARGS(1);

}  // namespace sweetspot
