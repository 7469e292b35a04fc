// JSON text whose objects each name a key once. nlohmann-json keeps the last of two equal
// keys without a word, so a saved round or a launch-monitor message that gives a key twice
// would be read as one of them by guess; these are refused instead.
#pragma once

#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

namespace sweetspot {

/// Parses `text`, refusing a key given twice in one object; keys match without case
/// ("Speed" and "speed" are the same key). InputError: "ROOT.KEY is given twice ..." (the
/// object's path from `root`), or "malformed JSON: ..." with the parser's position.
nlohmann::json parse_json_unique_keys(std::string_view text, const std::string& root);

/// `s` in lower case (ASCII).
std::string ascii_lower(std::string s);

}  // namespace sweetspot
