// The pause menu's keys (game/app/pause_menu.hpp): a restart that would throw play away asks
// first, so Esc then R (the replay key in play) never loses a round at one press.
#include <catch2/catch.hpp>

#include <GLFW/glfw3.h>

#include "game/app/pause_menu.hpp"

using namespace sweetspot;

TEST_CASE("a restart that loses play takes R twice; one with nothing to lose takes it once", "[pause]") {
  PauseMenu m;
  CHECK(m.key(GLFW_KEY_R, "") == MenuChoice::Restart);
  CHECK(!m.confirming());

  const std::string loses = "this hole's 3 strokes";
  CHECK(m.key(GLFW_KEY_R, loses) == MenuChoice::None);
  CHECK(m.confirming());
  CHECK(m.key(GLFW_KEY_R, loses) == MenuChoice::Restart);
  CHECK(!m.confirming());
  // The button asks the same way.
  CHECK(m.restart_pressed(loses) == MenuChoice::None);
  CHECK(m.restart_pressed(loses) == MenuChoice::Restart);
}

TEST_CASE("while a restart waits for R again, Esc keeps the play and the menu; other choices go on", "[pause]") {
  const std::string loses = "this session's 12 swings";
  PauseMenu m;
  REQUIRE(m.key(GLFW_KEY_R, loses) == MenuChoice::None);
  CHECK(m.key(GLFW_KEY_ESCAPE, loses) == MenuChoice::None);  // the question goes, the pause stays
  CHECK(!m.confirming());
  CHECK(m.key(GLFW_KEY_R, loses) == MenuChoice::None);      // asked afresh
  CHECK(m.key(GLFW_KEY_SPACE, loses) == MenuChoice::None);  // any other key: not now
  CHECK(m.key(GLFW_KEY_R, loses) == MenuChoice::None);
  CHECK(m.key(GLFW_KEY_TAB, loses) == MenuChoice::NextMode);
  CHECK(!m.confirming());
  CHECK(m.key(GLFW_KEY_ESCAPE, loses) == MenuChoice::Resume);
  CHECK(m.key(GLFW_KEY_Q, loses) == MenuChoice::Quit);
  // A reset (the menu closed) forgets a question left open.
  REQUIRE(m.key(GLFW_KEY_R, loses) == MenuChoice::None);
  m.reset();
  CHECK(m.key(GLFW_KEY_R, loses) == MenuChoice::None);
}

TEST_CASE("a quit that loses play takes Q twice; one with nothing to lose takes it once", "[pause]") {
  PauseMenu m;
  CHECK(m.key(GLFW_KEY_Q, "this hole's 3 strokes", "") == MenuChoice::Quit);  // the round was saved: nothing to lose
  const std::string round = "the round so far";
  CHECK(m.key(GLFW_KEY_Q, "", round) == MenuChoice::None);
  CHECK(m.asking() == MenuChoice::Quit);
  CHECK(m.key(GLFW_KEY_ESCAPE, "", round) == MenuChoice::None);  // kept: the menu stays, the question goes
  CHECK(!m.confirming());
  CHECK(m.key(GLFW_KEY_Q, "", round) == MenuChoice::None);
  CHECK(m.key(GLFW_KEY_Q, "", round) == MenuChoice::Quit);
  CHECK(!m.confirming());
  // A restart asked, then Q: the question turns to the quit, and R then asks the restart again.
  CHECK(m.key(GLFW_KEY_R, "this hole's 3 strokes", round) == MenuChoice::None);
  CHECK(m.key(GLFW_KEY_Q, "this hole's 3 strokes", round) == MenuChoice::None);
  CHECK(m.asking() == MenuChoice::Quit);
  CHECK(m.key(GLFW_KEY_R, "this hole's 3 strokes", round) == MenuChoice::None);
  CHECK(m.asking() == MenuChoice::Restart);
  // The button asks the same way.
  m.reset();
  CHECK(m.quit_pressed(round) == MenuChoice::None);
  CHECK(m.quit_pressed(round) == MenuChoice::Quit);
}
