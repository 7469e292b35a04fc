// A sport as data (assets/sports.toml): which ball, equipment and world it uses, where the
// ball sits at contact, the display units and the launch-monitor rows. Code asks the
// profile instead of branching on "golf or baseball", so a putter, a tee or no tee, a
// pitching machine are data.
#pragma once

#include <map>
#include <optional>
#include <string>
#include <vector>

namespace sweetspot {

/// What strikes the ball in this sport (the ShotSpec strike a scenario of it builds).
enum class ImpactorKind { Club, Bat };
const char* to_string(ImpactorKind k);

struct SportProfile {
  std::string name;              ///< "golf", "baseball": the scenario's `sport` value
  std::string ball;              ///< default ball (assets/equipment/balls.toml)
  ImpactorKind impactor = ImpactorKind::Club;
  std::string default_impactor;  ///< default club or bat name
  std::string default_world;     ///< world asset ("golf_hole", "ballpark")
  std::string default_aero;      ///< aero model ("ferguson2022", "nathan")
  std::string default_scenario;  ///< built-in scenario the window opens with
  std::string rules;             ///< game/rules set: "golf" or "baseball"
  /// Height of the ball's centre above the ground at contact (m); unset = the ball rests on
  /// the ground (its radius, plus the club's tee height when teed). Baseball: 0.9 m, a
  /// belt-high pitch over the plate.
  std::optional<double> contact_height;
  std::string distance_unit = "yd";  ///< imperial display unit of distances: "yd" or "ft"
  std::vector<std::string> report;   ///< launch-monitor rows: metric ids (game/report/metrics.hpp)
  std::vector<std::string> csv;      ///< CSV columns: metric ids
  /// Where the file set each key ("…/sports.toml:12"), so a name checked against the other
  /// assets later (the ball, the world, the aero model) is refused at its own line.
  std::map<std::string, std::string, std::less<>> source;
};

/// The set of sports a build knows (loaded once by Assets).
struct SportCatalog {
  std::vector<SportProfile> sports;
  /// The profile named `name`; throws InputError listing the names.
  const SportProfile& get(std::string_view name) const;
  /// "golf, baseball".
  std::string names() const;
};

}  // namespace sweetspot
