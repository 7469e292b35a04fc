// The pause menu's choices and its keys. A restart that would throw play away (a hole's
// strokes, a session's swings) asks first: R (or the button) once says what goes, R again
// restarts, anything else keeps it. Esc then R is also how a player reaching for the replay
// (R in play) would land here, so one press never loses a round.
#pragma once

#include <string>

namespace sweetspot {

enum class MenuChoice { None, Resume, Restart, NextMode, Quit };

class PauseMenu {
 public:
  /// A key pressed while paused (GLFW key code). `loses`: what a restart would throw away
  /// (ModeView::restart_loses), empty when nothing.
  MenuChoice key(int glfw_key, const std::string& loses);
  /// The restart button pressed (the same rule as R).
  MenuChoice restart_pressed(const std::string& loses);
  /// A restart has been asked for and waits for R again.
  bool confirming() const { return confirming_; }
  /// The menu closed (resumed, restarted, left): a later pause starts unasked.
  void reset() { confirming_ = false; }

 private:
  bool confirming_ = false;
};

/// Draws the menu (`title`: the mode's name; `restart_label`: "Restart hole") with its right
/// edge at `right` px, half way down a window `h` px high, with the question when a restart
/// waits for R again; the button clicked, if any.
MenuChoice draw_pause_menu(PauseMenu& menu, const char* title, const char* restart_label, const std::string& loses, float right,
                           int h);

}  // namespace sweetspot
