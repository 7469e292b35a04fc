#include "game/app/pause_menu.hpp"

#include <GLFW/glfw3.h>
#include <imgui.h>

namespace sweetspot {

MenuChoice PauseMenu::restart_pressed(const std::string& loses) {
  if (loses.empty() || confirming_) {
    confirming_ = false;
    return MenuChoice::Restart;
  }
  confirming_ = true;
  return MenuChoice::None;
}

MenuChoice PauseMenu::key(int glfw_key, const std::string& loses) {
  if (glfw_key == GLFW_KEY_R) return restart_pressed(loses);
  MenuChoice c = MenuChoice::None;
  if (glfw_key == GLFW_KEY_ESCAPE || glfw_key == GLFW_KEY_ENTER || glfw_key == GLFW_KEY_KP_ENTER) c = MenuChoice::Resume;
  else if (glfw_key == GLFW_KEY_TAB) c = MenuChoice::NextMode;
  else if (glfw_key == GLFW_KEY_Q) c = MenuChoice::Quit;
  // Any other key is an answer too: not now. The menu stays, the question goes.
  if (confirming_) {
    confirming_ = false;
    return c == MenuChoice::Resume ? MenuChoice::None : c;
  }
  return c;
}

MenuChoice draw_pause_menu(PauseMenu& menu, const char* title, const char* restart_label, const std::string& loses, float right,
                           int h) {
  MenuChoice choice = MenuChoice::None;
  // Half way down: under a mode's launch monitor panel at the top.
  ImGui::SetNextWindowPos(ImVec2(right, 0.58f * static_cast<float>(h)), ImGuiCond_Always, ImVec2(1.0f, 0.5f));
  ImGui::SetNextWindowSize(ImVec2(300, 0), ImGuiCond_Always);
  ImGui::Begin("Paused", nullptr, ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse);
  ImGui::Text("%s", title);
  ImGui::Separator();
  const ImVec2 size(-1, 0);
  if (menu.confirming()) {
    ImGui::TextWrapped("%s: %s will be lost.", restart_label, loses.c_str());
    if (ImGui::Button((std::string(restart_label) + " (R again)").c_str(), size)) choice = menu.restart_pressed(loses);
    if (ImGui::Button("Keep it (Esc)", size)) menu.reset();
  } else {
    if (ImGui::Button("Resume (Esc)", size)) choice = MenuChoice::Resume;
    if (ImGui::Button((std::string(restart_label) + " (R)").c_str(), size)) choice = menu.restart_pressed(loses);
  }
  if (ImGui::Button("Next mode (Tab)", size)) choice = MenuChoice::NextMode;
  if (ImGui::Button("Quit (Q)", size)) choice = MenuChoice::Quit;
  ImGui::End();
  return choice;
}

}  // namespace sweetspot
