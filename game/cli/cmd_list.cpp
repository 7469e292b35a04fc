// `sweetspot list`: the built-in scenarios with a one-line description each.
#include <iostream>

#include "game/cli/command.hpp"
#include "game/content/scenario.hpp"
#include "game/util/terminal_text.hpp"

namespace sweetspot::cli {
namespace {

RunFn setup_list(CLI::App& /*sub*/) {
  return [](const Assets& assets) -> int {
    const auto& all = assets.scenarios();
    std::size_t width = 0;
    for (const auto& s : all) width = std::max(width, s.name.size());
    for (const auto& s : all) {
      // A scenario file is text from outside: its description prints with nothing a
      // terminal acts on.
      std::cout << terminal_safe(s.name) << std::string(width + 2 - s.name.size(), ' ')
                << terminal_safe(scenario_description(s)) << "\n";
    }
    return 0;
  };
}

const CommandRegistrar list_command{90, "list", "list the built-in scenarios", setup_list};

}  // namespace
}  // namespace sweetspot::cli
