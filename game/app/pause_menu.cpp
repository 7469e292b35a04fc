#include "game/app/pause_menu.hpp"

#include <GLFW/glfw3.h>
#include <imgui.h>

namespace sweetspot {

MenuChoice PauseMenu::ask(MenuChoice c, const std::string& loses) {
  if (loses.empty() || asking_ == c) {
    asking_ = MenuChoice::None;
    return c;
  }
  asking_ = c;
  return MenuChoice::None;
}

MenuChoice PauseMenu::key(int glfw_key, const std::string& restart_loses, const std::string& quit_loses) {
  if (glfw_key == GLFW_KEY_R) return ask(MenuChoice::Restart, restart_loses);
  if (glfw_key == GLFW_KEY_Q) return ask(MenuChoice::Quit, quit_loses);
  MenuChoice c = MenuChoice::None;
  if (glfw_key == GLFW_KEY_ESCAPE || glfw_key == GLFW_KEY_ENTER || glfw_key == GLFW_KEY_KP_ENTER) c = MenuChoice::Resume;
  else if (glfw_key == GLFW_KEY_TAB) c = MenuChoice::NextMode;
  // Any other key is an answer too: not now. The menu stays, the question goes.
  if (asking_ != MenuChoice::None) {
    asking_ = MenuChoice::None;
    return c == MenuChoice::Resume ? MenuChoice::None : c;
  }
  return c;
}

MenuChoice draw_pause_menu(PauseMenu& menu, const char* title, const char* restart_label, const std::string& restart_loses,
                           const std::string& quit_loses, float right, int h) {
  MenuChoice choice = MenuChoice::None;
  // Half way down: under a mode's launch monitor panel at the top.
  ImGui::SetNextWindowPos(ImVec2(right, 0.58f * static_cast<float>(h)), ImGuiCond_Always, ImVec2(1.0f, 0.5f));
  ImGui::SetNextWindowSize(ImVec2(300, 0), ImGuiCond_Always);
  ImGui::Begin("Paused", nullptr, ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse);
  ImGui::Text("%s", title);
  ImGui::Separator();
  const ImVec2 size(-1, 0);
  if (menu.asking() == MenuChoice::Restart) {
    ImGui::TextWrapped("%s: %s will be lost.", restart_label, restart_loses.c_str());
    if (ImGui::Button((std::string(restart_label) + " (R again)").c_str(), size)) choice = menu.restart_pressed(restart_loses);
    if (ImGui::Button("Keep it (Esc)", size)) menu.reset();
  } else if (menu.asking() == MenuChoice::Quit) {
    ImGui::TextWrapped("Quit: %s will be lost.", quit_loses.c_str());
    if (ImGui::Button("Quit (Q again)", size)) choice = menu.quit_pressed(quit_loses);
    if (ImGui::Button("Keep it (Esc)", size)) menu.reset();
  } else {
    if (ImGui::Button("Resume (Esc)", size)) choice = MenuChoice::Resume;
    if (ImGui::Button((std::string(restart_label) + " (R)").c_str(), size)) choice = menu.restart_pressed(restart_loses);
  }
  if (ImGui::Button("Next mode (Tab)", size)) choice = MenuChoice::NextMode;
  if (menu.asking() != MenuChoice::Quit && ImGui::Button("Quit (Q)", size)) choice = menu.quit_pressed(quit_loses);
  ImGui::End();
  return choice;
}

}  // namespace sweetspot
