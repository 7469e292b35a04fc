#include "game/content/json_unique_keys.hpp"

#include <algorithm>
#include <cctype>
#include <unordered_set>
#include <vector>

#include "physics/error.hpp"

namespace sweetspot {

std::string ascii_lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return s;
}

nlohmann::json parse_json_unique_keys(std::string_view text, const std::string& root) {
  std::vector<std::unordered_set<std::string>> seen;  // the keys of each open object
  std::vector<std::string> names{root};               // what each open object is called
  std::string last_key, duplicate;
  const nlohmann::json::parser_callback_t check = [&](int, nlohmann::json::parse_event_t event, nlohmann::json& parsed) {
    using E = nlohmann::json::parse_event_t;
    if (event == E::object_start) {
      if (!seen.empty()) names.push_back(last_key.empty() ? std::string("(array item)") : last_key);
      seen.emplace_back();
    } else if (event == E::object_end) {
      if (!seen.empty()) seen.pop_back();
      if (names.size() > 1) names.pop_back();
      last_key.clear();
    } else if (event == E::key && !seen.empty()) {
      last_key = parsed.get<std::string>();
      if (!seen.back().insert(ascii_lower(last_key)).second && duplicate.empty())
        duplicate = names.back() + "." + last_key;
    } else if (event == E::array_start) {
      last_key.clear();
    }
    return true;
  };
  nlohmann::json j;
  try {
    j = nlohmann::json::parse(text, check);
  } catch (const nlohmann::json::exception& e) {
    // The parser's own words without its "[json.exception.kind.id] " tag, bytes that are not
    // printable ASCII written as \xNN, and the key whose value it was reading.
    std::string why = e.what();
    if (const std::size_t tag = why.find("] "); why.rfind("[json.exception.", 0) == 0 && tag != std::string::npos)
      why.erase(0, tag + 2);
    std::string clean;
    for (const char c : why) {
      const auto u = static_cast<unsigned char>(c);
      if (u >= 0x20 && u < 0x7f) {
        clean += c;
      } else {
        static const char* hex = "0123456789ABCDEF";
        clean += std::string("\\x") + hex[u >> 4] + hex[u & 15];
      }
    }
    const std::string at = last_key.empty() ? std::string() : " in " + names.back() + "." + last_key;
    throw InputError("malformed JSON" + at + ": " + clean);
  }
  if (!duplicate.empty()) throw InputError(duplicate + " is given twice (keys match without case)");
  return j;
}

}  // namespace sweetspot
