// A golf course file (assets/courses/NAME.toml, DESIGN §9): an ordered list of holes, each
// a world asset with a par, a tee spot and a cup. Loaded and checked here; the game plays it
// (game/modes/golf).
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "game/content/assets.hpp"
#include "physics/math.hpp"
#include "physics/range.hpp"

namespace sweetspot {

struct CourseHole {
  int number = 1;                 ///< as printed on the card
  int par = 4;
  static constexpr Range kPar{3.0, 6.0};
  const WorldAsset* world = nullptr;  ///< never null once loaded
  std::string world_name;
  Vec3 tee = Vec3::Zero();        ///< m, the tee spot on the ground (world frame)
  Vec3 pin = Vec3::Zero();        ///< m, the cup's centre on the green
  /// Stroke index: 1 the hole where a handicap's first stroke is given (the hardest), a
  /// permutation of 1..n over the course. Default: by length, the longest hole 1.
  int stroke_index = 1;
  /// The hole's wind when the course states one (else the round draws it from its seed).
  std::optional<double> wind_speed;      ///< m/s at 10 m; Environment::kWindSpeed
  double wind_toward = 0.0;              ///< rad right of the world's +x the wind blows toward
  double length() const;          ///< m, tee to cup along the ground
};

struct Course {
  std::string name;               ///< "Sweetspot Links"
  std::filesystem::path source;   ///< the .toml it came from
  std::vector<CourseHole> holes;  ///< in playing order
  int par() const;
};

/// A course by name ("links": <assets>/courses/links.toml) or by path (its .toml, or a course
/// directory holding course.toml, as course import writes one). Throws InputError
/// naming file:line and the key for a missing tee, a world without a cup and no `pin`, a
/// tee or cup off the world's ground, a par outside [3, 6], hole numbers out of order, stroke
/// indexes that are not 1..n each once, a wind out of range.
Course load_course(const Assets& assets, std::string_view name_or_path);

/// Names of the shipped courses (<assets>/courses/*.toml), sorted.
std::vector<std::string> course_names(const Assets& assets);

}  // namespace sweetspot
