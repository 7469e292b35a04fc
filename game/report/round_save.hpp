// A golf round saved to resume later: who plays, the format and options, the course, and
// every turn so far (JSON). Resuming replays the turns onto a new round: the physics and the
// bots are deterministic, so the round continues bit for bit as if never stopped.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "game/modes/golf/golf_group.hpp"

namespace sweetspot {

struct SavedRound {
  std::string course;               ///< as load_course() takes it (a name or a path)
  int holes = 0;                    ///< the round's holes: the course's first N (play --holes N)
  CourseSetup setup;                ///< its tees and pin set
  std::vector<GolfPlayer> players;
  GolfOptions options;
  std::vector<GolfEvent> events;
  /// The window's own record of the round, which the turns do not hold: each hole's
  /// restarts from the pause menu (the card's R marks) and the swings cancelled with Esc.
  /// A save without them (`round --save`, older saves) has none.
  std::vector<int> restarts;
  int cancelled = 0;
  std::string source;               ///< where it was read from (for messages)
};

/// The save's JSON. `course` names the course as load_course() will find it again;
/// `restarts` and `cancelled` as SavedRound has them (the window's; none from `round`).
nlohmann::json round_save_json(const GolfGroup& group, const std::string& course, const std::vector<int>& restarts = {},
                               int cancelled = 0);
/// Reads a save; InputError naming the file and the key (with the allowed values) when it is
/// not one. Nothing is played yet: resume_round() does that.
SavedRound read_round_save(const std::filesystem::path& path);
SavedRound parse_round_save(const std::string& text, const std::string& source);
/// The saved round's course: its first `holes` holes. InputError when it has fewer.
Course saved_course(const Assets& assets, const SavedRound& saved);
/// The saved round, its turns replayed.
GolfGroup resume_round(const Assets& assets, const SavedRound& saved);

}  // namespace sweetspot
