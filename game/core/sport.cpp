#include "game/core/sport.hpp"

#include "physics/error.hpp"

namespace sweetspot {

const char* to_string(ImpactorKind k) { return k == ImpactorKind::Club ? "club" : "bat"; }

const SportProfile& SportCatalog::get(std::string_view name) const {
  for (const auto& s : sports)
    if (s.name == name) return s;
  throw InputError("unknown sport '" + std::string(name) + "' (allowed: " + names() + ")");
}

std::string SportCatalog::names() const {
  std::string out;
  for (const auto& s : sports) out += (out.empty() ? "" : ", ") + s.name;
  return out;
}

}  // namespace sweetspot
