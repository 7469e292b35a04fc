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
  /// m, where the hole's line bends between tee and cup, in order (a dogleg's corner): where
  /// a player aims when the cup is out of reach or out of sight. Empty: straight.
  std::vector<Vec3> bends;
  static constexpr std::size_t kMaxBends = 8;
  /// m, more cup positions on the green: pin sets 2, 3, ... (`pin` is set 1).
  std::vector<Vec3> more_pins;
  static constexpr std::size_t kMaxPins = 8;
  /// Named tee sets ("blue", "white", "red") where the map gives them; `tee` plays otherwise.
  struct TeeSet {
    std::string name;
    Vec3 at = Vec3::Zero();
  };
  std::vector<TeeSet> tee_sets;
  static constexpr std::size_t kMaxTeeSets = 8;
  /// Stroke index: 1 the hole where a handicap's first stroke is given (the hardest), a
  /// permutation of 1..n over the course. Default: by length, the longest hole 1.
  int stroke_index = 1;
  /// The hole's wind when the course states one (else the round draws it from its seed).
  std::optional<double> wind_speed;      ///< m/s at 10 m; Environment::kWindSpeed
  double wind_toward = 0.0;              ///< rad right of the world's +x the wind blows toward
  double length() const;          ///< m, tee to cup along the line (through the bends), level
};

/// The day's set-up of a course: which tees the players play from and where the cups are.
struct CourseSetup {
  std::string tees;   ///< a tee set's name; "" the holes' own tees
  /// 1: each hole's `pin`; k: its (k-1)th of more_pins (cycling through its own); 0: a
  /// tournament's mix, the holes taking their sets in turn (hole n its set n, cycling through
  /// its own), so a round meets a middle pin on some greens and edge pins on the rest.
  int pin_set = 1;
  static constexpr Range kPinSet{0.0, 9.0};
  /// What `round` and `play` cut when not told: the mix. A course's `pin` is its green's middle
  /// when course import places it (the importer's sets 2.. sit toward the edges), and every
  /// cup in the middle makes the tour bot a 66.7 shooter hitting 86 % of the greens (the
  /// National, 10 calm rounds; the mix: docs/courses.md).
  static constexpr int kDayPinSet = 0;
};

struct Course {
  std::string name;               ///< "Sweetspot Links"
  CourseSetup setup;              ///< as set_up() last moved its tees and cups
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

/// Moves every hole's tee and cup as `setup` says. Throws InputError naming the tee set when
/// no hole has it (listing those the course has); a hole without it keeps its own tee.
/// A refusal names the setting by `tees_key` and `pins_key` (a save file's keys by default;
/// the command line passes its flags).
void set_up(Course& course, const CourseSetup& setup, const char* tees_key = "tees", const char* pins_key = "pin set");
/// The tee sets of any hole of `course`, in the order first met.
std::vector<std::string> tee_set_names(const Course& course);

/// Names of the shipped courses (<assets>/courses/*.toml), sorted.
std::vector<std::string> course_names(const Assets& assets);

}  // namespace sweetspot
