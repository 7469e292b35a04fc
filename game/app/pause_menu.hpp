// The pause menu's choices and its keys. A restart or a quit that would throw play away (a
// hole's strokes, a round not saved, a session's swings) asks first: R (or Q, or the button)
// once says what goes, the same again does it, anything else keeps it. Esc then R is also how
// a player reaching for the replay (R in play) would land here, so one press never loses a
// round; Q beside Tab and Esc likewise.
#pragma once

#include <string>

namespace sweetspot {

enum class MenuChoice { None, Resume, Restart, NextMode, Quit };

class PauseMenu {
 public:
  /// A key pressed while paused (GLFW key code). `restart_loses` / `quit_loses`: what a
  /// restart / a quit would throw away (ModeView::restart_loses, quit_loses), empty when
  /// nothing.
  MenuChoice key(int glfw_key, const std::string& restart_loses, const std::string& quit_loses = {});
  /// The restart button pressed (the same rule as R).
  MenuChoice restart_pressed(const std::string& loses) { return ask(MenuChoice::Restart, loses); }
  /// The quit button pressed (the same rule as Q).
  MenuChoice quit_pressed(const std::string& loses) { return ask(MenuChoice::Quit, loses); }
  /// A restart or a quit has been asked for and waits for its key again.
  bool confirming() const { return asking_ != MenuChoice::None; }
  /// Which: Restart or Quit (None when nothing is asked).
  MenuChoice asking() const { return asking_; }
  /// The menu closed (resumed, restarted, left): a later pause starts unasked.
  void reset() { asking_ = MenuChoice::None; }

 private:
  MenuChoice ask(MenuChoice c, const std::string& loses);
  MenuChoice asking_ = MenuChoice::None;
};

/// Draws the menu (`title`: the mode's name; `restart_label`: "Restart hole") with its right
/// edge at `right` px, half way down a window `h` px high, with the question when a restart
/// or a quit waits for its key again; the button clicked, if any.
MenuChoice draw_pause_menu(PauseMenu& menu, const char* title, const char* restart_label, const std::string& restart_loses,
                           const std::string& quit_loses, float right, int h);

}  // namespace sweetspot
