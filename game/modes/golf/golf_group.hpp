// A round for one to four golfers, each a human or a bot, playing the same holes in turn
// (DESIGN §9 "Players and formats"): honours on the tee (Rule 6.4a), the ball farthest from
// the hole next (Rule 6.4b), every player's card kept by GolfRound, handicap strokes by the
// holes' stroke index, the format's result from the cards (game/rules/golf_scoring).
// Options a group of friends sets: gimmes (putts this close conceded), auto-putt (a human's
// putts played by the physics with their skill's putting). Every turn is recorded as an event,
// so a saved round replays to the same state and continues bit for bit.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "game/modes/golf/bot.hpp"
#include "game/modes/golf/round.hpp"
#include "game/rules/golf_scoring.hpp"

namespace sweetspot {

struct GolfPlayer {
  std::string name;            ///< as the card shows it
  std::string skill = "tour";  ///< golfer_skill(): swing speed, and a bot's errors
  bool human = false;
  int handicap = 0;            ///< course handicap for 18 holes, [0, kMaxHandicap]
  /// The carries this player measured (a bag-gapping session) for their caddie's clubs
  /// (empty: the skill's full swings on flat fairway).
  std::vector<GolfBot::Stock> bag;
};

struct GolfOptions {
  GolfFormat format = GolfFormat::Stroke;
  /// A ball at rest on the green this close to the cup is holed with the next stroke, not
  /// played (0 = off). Match play concedes short putts by custom (Rule 3.2b allows it); stroke
  /// play has no gimmes, so the default is off there.
  double gimme_m = 0.0;
  static constexpr Range kGimme{0.0, 3.0};  ///< m: up to "inside the leather" and well beyond
  bool auto_putt = false;      ///< humans' putts played by their skill's putting bot
  std::uint64_t seed = 1;      ///< the winds and the bots' errors
};

/// Match play's customary gimme, "inside the leather": from the putter's head to the bottom
/// of its grip, about 0.6 m on a 34 in (0.86 m) putter with a 10.5 in (0.27 m) grip.
inline constexpr double kMatchGimme = 0.6;  // m

/// One turn of a round: a stroke played (a human's, or the bot's plan, or a conceded putt),
/// or a hole given up.
struct GolfEvent {
  enum class Kind { Stroke, ConcedeStroke, ConcedeHole };
  int player = 0;
  Kind kind = Kind::Stroke;
  StrokeInput stroke;          ///< Kind::Stroke
  /// The stroke was the player's bot's draw (a bot, auto-putt, the caddie playing for a
  /// human): a replay draws it again, so the bot's generator stays in step.
  bool drawn = false;
};

class GolfGroup {
 public:
  /// Refuses (InputError naming the player or option) 0 or more than 4 players, a handicap out
  /// of [0, 54], match play for other than two, a gimme out of range.
  GolfGroup(const Assets& assets, const Course& course, std::vector<GolfPlayer> players, GolfOptions options);

  /// The round is over: every hole played, or in match play the match decided (one side
  /// leads by more holes than remain, Rule 3.2a(3)), when the holes left are not played.
  bool finished() const { return next_ < 0; }
  /// Match play: one side leads by more holes than remain after the holes finished.
  bool match_decided() const;
  /// Match play: who won hole `hole` (an index into the holes the group has finished) and
  /// where the match then stood, "Hole 2 halved: scratch bot 1 up", "You win hole 3: all
  /// square"; empty for a hole not yet finished.
  std::string match_hole_words(std::size_t hole) const;
  std::size_t hole_index() const { return hole_; }  ///< the hole the group is on; once finished, the holes played
  const Course& course() const { return course_; }
  const std::vector<GolfPlayer>& players() const { return players_; }
  const GolfOptions& options() const { return options_; }
  const GolfRound& round(int player) const { return rounds_.at(static_cast<std::size_t>(player)); }
  const std::vector<HoleWind>& winds() const { return winds_; }
  /// Whose turn it is; -1 once the round is over.
  int to_play() const { return next_; }
  /// The player to play is a bot, or a human whose putt auto-putt plays.
  bool bot_turn() const;
  /// The stroke the bot to play means to play, its errors drawn (advances its generator).
  StrokeInput bot_stroke();
  /// The player's caddie: a bot of their skill that suggests clubs (and the bag they carry).
  const GolfBot& caddie(int player) const { return bots_.at(static_cast<std::size_t>(player)); }

  /// Plays the turn's stroke. `shot` receives the physics (for drawing).
  const StrokeRecord& play(const StrokeInput& in, ShotResult* shot = nullptr);
  /// The turn played by the player's bot (its plan, errors drawn): a bot's turn, or the
  /// caddie playing for a human.
  const StrokeRecord& play_bot(ShotResult* shot = nullptr);
  /// Plays a stroke bot_stroke() drew (a caller that shows the bot's choice first).
  const StrokeRecord& play_drawn(const StrokeInput& drawn, ShotResult* shot = nullptr) { return play_stroke(drawn, true, shot); }
  /// The player to play gives up the hole (match play only: InputError otherwise).
  void concede_hole();
  /// Match play: the player to play can no longer halve the hole, his opponent having holed
  /// out in fewer net strokes than his next stroke would make his score. A bot then gives the
  /// hole up (concede_hole) instead of putting out, as match players pick up (Rule 3.2b(1)).
  bool hole_lost_for_next() const;

  /// Every turn so far, in order: a round given these replays to this state.
  const std::vector<GolfEvent>& events() const { return events_; }
  /// The index in events() of the first turn on hole `hole` (0-based) once the group is on
  /// it or past it; events().size() for a hole not reached.
  std::size_t hole_first_event(std::size_t hole) const {
    return hole < hole_first_events_.size() ? hole_first_events_[hole] : events_.size();
  }
  /// Replays `events` onto a new round (bot turns redrawn and checked against the record:
  /// InputError naming the event when the record is not this game's).
  void replay(const std::vector<GolfEvent>& events);

  /// Strokes each hole gives the player: full handicap in stroke, stableford and skins; in
  /// match play the difference to the lower handicap (WHS Appendix C: 100 % for singles).
  std::vector<int> strokes_received(int player) const;
  /// Gross minus strokes received, per completed hole.
  std::vector<int> net(int player) const;
  /// What happened on the last turn that a player must be told ("picked up at 10 strokes",
  /// "the 0.4 m putt is conceded"); empty otherwise.
  const std::string& note() const { return note_; }

 private:
  /// The match over the holes the whole group has finished.
  MatchResult match_so_far() const;
  const StrokeRecord& play_stroke(const StrokeInput& in, bool drawn, ShotResult* shot);
  void after_turn(int player, std::size_t hole_before);
  void choose_next();
  std::vector<int> honour_order() const;

  Course course_;
  std::vector<GolfPlayer> players_;
  GolfOptions options_;
  std::vector<HoleWind> winds_;
  std::vector<GolfRound> rounds_;
  std::vector<GolfBot> bots_;
  std::vector<int> order_;      ///< the honour on the current hole's tee
  std::size_t hole_ = 0;
  std::vector<std::size_t> hole_first_events_{0};  ///< per hole reached
  int next_ = 0;
  std::vector<GolfEvent> events_;
  std::string note_;
};

}  // namespace sweetspot
