#include "game/net/session_file.hpp"

#include <filesystem>
#include <sstream>

#include "game/content/toml_file.hpp"
#include "physics/error.hpp"

namespace sweetspot {

SessionFile read_session_file(const std::string& path, const std::string& why) {
  SessionFile f;
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) return f;  // a new session
  f.text = read_data_file(path, "session", 256u << 20);
  std::istringstream in(f.text);
  int number = 0;
  for (std::string line; std::getline(in, line);) {
    ++number;
    if (line.find_first_not_of(" \t\r") == std::string::npos) continue;
    nlohmann::json j = nlohmann::json::parse(line, nullptr, false);
    if (!j.is_object()) throw InputError(path + ":" + std::to_string(number) + ": not a session line (" + why + ")");
    f.lines.push_back({number, std::move(j)});
  }
  if (!f.text.empty() && f.text.back() != '\n') f.text += '\n';
  return f;
}

}  // namespace sweetspot
