#include "game/report/round_save.hpp"

#include <algorithm>
#include <cmath>

#include "game/content/course_file.hpp"
#include "game/content/json_unique_keys.hpp"
#include "game/content/toml_file.hpp"
#include "game/util/terminal_text.hpp"
#include "physics/error.hpp"
#include "physics/range.hpp"

namespace sweetspot {
namespace {

constexpr int kVersion = 1;
constexpr std::uintmax_t kMaxSaveBytes = 16u << 20;  // a 4-player 18-hole round is ~40 kB

const char* kind_name(GolfEvent::Kind k) {
  return k == GolfEvent::Kind::ConcedeHole ? "concede_hole" : "stroke";
}

// The JSON reader's checks: each names the key and what is allowed.
struct Reader {
  std::string source;
  [[noreturn]] void fail(const std::string& key, const std::string& why) const {
    throw InputError(source + ": " + key + ": " + why);
  }
  const nlohmann::json& at(const nlohmann::json& j, const std::string& key, const std::string& path) const {
    if (!j.is_object() || !j.contains(key)) fail(path + key, "missing");
    return j.at(key);
  }
  std::string text(const nlohmann::json& j, const std::string& key, const std::string& path = "") const {
    const auto& v = at(j, key, path);
    if (!v.is_string()) fail(path + key, "must be a string");
    return v.get<std::string>();
  }
  double number(const nlohmann::json& j, const std::string& key, const Range& r, const std::string& path = "") const {
    const auto& v = at(j, key, path);
    if (!v.is_number()) fail(path + key, "must be a number");
    const double x = v.get<double>();
    if (!r.contains(x)) {
      const std::string refusal = range_refusal(key, x, r, "");  // "key = 1e+308 is out of range (allowed ...)"
      fail(path + key, refusal.substr(refusal.find(" = ") + 3));
    }
    return x;
  }
  bool flag(const nlohmann::json& j, const std::string& key, const std::string& path = "") const {
    const auto& v = at(j, key, path);
    if (!v.is_boolean()) fail(path + key, "must be true or false");
    return v.get<bool>();
  }
  // A key the reader does not know would be dropped without a word (a misspelt "sed" for
  // "seed"); the save names every key it has.
  void only_keys(const nlohmann::json& j, std::initializer_list<const char*> keys, const std::string& path) const {
    if (!j.is_object()) fail(path.empty() ? std::string("(top level)") : path.substr(0, path.size() - 1), "must be an object");
    for (auto it = j.begin(); it != j.end(); ++it)
      if (std::none_of(keys.begin(), keys.end(), [&](const char* k) { return it.key() == k; })) {
        std::string allowed;
        for (const char* k : keys) allowed += (allowed.empty() ? "" : ", ") + std::string(k);
        fail(path + it.key(), "unknown key (allowed: " + allowed + ")");
      }
  }
  std::uint64_t whole(const nlohmann::json& j, const std::string& key, const std::string& path = "") const {
    const auto& v = at(j, key, path);
    if (!v.is_number_unsigned()) fail(path + key, "must be a whole number >= 0");
    return v.get<std::uint64_t>();
  }
};

}  // namespace

nlohmann::json round_save_json(const GolfGroup& g, const std::string& course, const std::vector<int>& restarts, int cancelled) {
  using nlohmann::json;
  json players = json::array();
  for (const GolfPlayer& p : g.players()) {
    json bag = json::array();
    for (const GolfBot::Stock& s : p.bag)
      bag.push_back({{"club", s.club}, {"carry_m", s.carry}, {"total_m", s.total}, {"spread_m", s.spread}, {"side_spread_m", s.side_spread}});
    players.push_back({{"name", p.name}, {"skill", p.skill}, {"human", p.human}, {"handicap", p.handicap}, {"bag", bag}});
  }
  json events = json::array();
  for (const GolfEvent& e : g.events()) {
    json ev = {{"player", e.player}, {"kind", kind_name(e.kind)}};
    if (e.kind == GolfEvent::Kind::Stroke) {
      ev["club"] = e.stroke.club;
      ev["aim_rad"] = e.stroke.aim;
      ev["power"] = e.stroke.meter.power;
      ev["accuracy_ms"] = e.stroke.meter.accuracy_ms;
      ev["drawn"] = e.drawn;
    }
    events.push_back(ev);
  }
  return {{"sweetspot_round", kVersion},     {"course", course}, {"holes", g.course().holes.size()},
          {"players", players},              {"format", to_string(g.options().format)},
          {"gimme_m", g.options().gimme_m},  {"auto_putt", g.options().auto_putt},
          {"seed", g.options().seed},        {"tees", g.course().setup.tees},
          {"pin_set", g.course().setup.pin_set}, {"events", events},
          {"restarts", restarts},            {"cancelled", cancelled}};
}

SavedRound parse_round_save(const std::string& text, const std::string& source) {
  nlohmann::json j;
  try {
    j = parse_json_unique_keys(text, "round");
  } catch (const InputError& e) {
    throw InputError(source + ": not a saved round (" + e.what() + ")");
  }
  const Reader r{source};
  if (!j.is_object() || !j.contains("sweetspot_round")) r.fail("sweetspot_round", "missing: not a saved round");
  r.only_keys(j, {"sweetspot_round", "course", "holes", "players", "format", "gimme_m", "auto_putt", "seed", "tees",
                  "pin_set", "events", "restarts", "cancelled"}, "");
  if (j["sweetspot_round"] != kVersion) r.fail("sweetspot_round", "version " + j["sweetspot_round"].dump() + " (allowed: 1)");
  SavedRound s;
  s.source = source;
  s.course = r.text(j, "course");
  static constexpr Range kHoles{1.0, 18.0};
  const double holes = r.number(j, "holes", kHoles);
  if (holes != static_cast<int>(holes)) r.fail("holes", "must be a whole number");
  s.holes = static_cast<int>(holes);
  const auto& players = r.at(j, "players", "");
  if (!players.is_array() || players.empty() || players.size() > 4) r.fail("players", "1 to 4 players");
  static constexpr Range kHandicap{0.0, kMaxHandicap};
  static constexpr Range kCarry{0.0, 500.0};  // m
  for (std::size_t i = 0; i < players.size(); ++i) {
    const std::string path = "players[" + std::to_string(i) + "].";
    GolfPlayer p;
    r.only_keys(players[i], {"name", "skill", "human", "handicap", "bag"}, path);
    p.name = r.text(players[i], "name", path);
    if (const std::string why = name_problem(p.name, 24); !why.empty())
      r.fail(path + "name", why + ": the card needs each player's name, 1 to 24 characters");
    p.skill = r.text(players[i], "skill", path);
    p.human = r.flag(players[i], "human", path);
    const double h = r.number(players[i], "handicap", kHandicap, path);
    if (h != static_cast<int>(h)) r.fail(path + "handicap", "must be a whole number");
    p.handicap = static_cast<int>(h);
    try {
      golfer_skill(p.skill);
    } catch (const InputError& e) {
      r.fail(path + "skill", e.what());
    }
    const auto& bag = r.at(players[i], "bag", path);
    if (!bag.is_array() || bag.size() > 14) r.fail(path + "bag", "a list of at most 14 clubs");
    for (std::size_t k = 0; k < bag.size(); ++k) {
      const std::string at = path + "bag[" + std::to_string(k) + "].";
      GolfBot::Stock st;
      r.only_keys(bag[k], {"club", "carry_m", "total_m", "spread_m", "side_spread_m"}, at);
      st.club = r.text(bag[k], "club", at);
      if (st.club == "putter" || std::find(golf_bag().begin(), golf_bag().end(), st.club) == golf_bag().end())
        r.fail(at + "club", "'" + st.club + "' is not a club of the bag (the putter has no carry)");
      st.carry = r.number(bag[k], "carry_m", kCarry, at);
      st.total = r.number(bag[k], "total_m", kCarry, at);
      st.spread = r.number(bag[k], "spread_m", kCarry, at);
      st.side_spread = r.number(bag[k], "side_spread_m", kCarry, at);
      p.bag.push_back(st);
    }
    s.players.push_back(p);
  }
  try {
    s.options.format = golf_format(r.text(j, "format"));
  } catch (const InputError& e) {
    r.fail("format", e.what());
  }
  s.options.gimme_m = r.number(j, "gimme_m", GolfOptions::kGimme);
  s.options.auto_putt = r.flag(j, "auto_putt");
  s.options.seed = r.whole(j, "seed");
  // The course's set-up (saves written before tee and pin sets play its own tees, pin set 1).
  if (j.contains("tees") && !j["tees"].is_string()) r.fail("tees", "a tee set's name (\"\" for the holes' own)");
  if (j.contains("tees")) s.setup.tees = j["tees"].get<std::string>();
  if (j.contains("pin_set")) {
    const double k = r.number(j, "pin_set", CourseSetup::kPinSet);
    if (k != static_cast<int>(k)) r.fail("pin_set", "must be a whole number");
    s.setup.pin_set = static_cast<int>(k);
  }
  // The window's record (optional: a headless round's save and older saves have none).
  static constexpr Range kCount{0.0, 1e6};
  if (j.contains("restarts")) {
    const auto& restarts = j["restarts"];
    if (!restarts.is_array() || restarts.size() > static_cast<std::size_t>(s.holes))
      r.fail("restarts", "a list of each hole's restarts, at most " + std::to_string(s.holes) + " (the round's holes)");
    for (std::size_t h = 0; h < restarts.size(); ++h) {
      const std::string at = "restarts[" + std::to_string(h) + "]";
      if (!restarts[h].is_number() || restarts[h].get<double>() < kCount.min || restarts[h].get<double>() > kCount.max ||
          restarts[h].get<double>() != std::floor(restarts[h].get<double>()))
        r.fail(at, "must be a whole number in [0, 1000000]");
      s.restarts.push_back(restarts[h].get<int>());
    }
  }
  if (j.contains("cancelled")) {
    const double c = r.number(j, "cancelled", kCount);
    if (c != std::floor(c)) r.fail("cancelled", "must be a whole number");
    s.cancelled = static_cast<int>(c);
  }
  const auto& events = r.at(j, "events", "");
  if (!events.is_array()) r.fail("events", "must be a list");
  const Range kPlayer{0.0, static_cast<double>(s.players.size() - 1)};
  for (std::size_t i = 0; i < events.size(); ++i) {
    const std::string path = "events[" + std::to_string(i) + "].";
    GolfEvent e;
    const double player = r.number(events[i], "player", kPlayer, path);
    if (player != static_cast<int>(player)) r.fail(path + "player", "must be a whole number");
    e.player = static_cast<int>(player);
    const std::string kind = r.text(events[i], "kind", path);
    if (kind == "concede_hole") {
      r.only_keys(events[i], {"player", "kind"}, path);
      e.kind = GolfEvent::Kind::ConcedeHole;
    } else if (kind == "stroke") {
      r.only_keys(events[i], {"player", "kind", "club", "aim_rad", "power", "accuracy_ms", "drawn"}, path);
      e.stroke.club = r.text(events[i], "club", path);
      if (std::find(golf_bag().begin(), golf_bag().end(), e.stroke.club) == golf_bag().end())
        r.fail(path + "club", "'" + e.stroke.club + "' is not a club of the bag");
      e.stroke.aim = r.number(events[i], "aim_rad", StrokeInput::kAim, path);
      e.stroke.meter.power = r.number(events[i], "power", MeterInput::kPower, path);
      e.stroke.meter.accuracy_ms = r.number(events[i], "accuracy_ms", MeterInput::kAccuracy, path);
      e.drawn = r.flag(events[i], "drawn", path);
    } else {
      r.fail(path + "kind", "'" + kind + "' (allowed: stroke, concede_hole)");
    }
    s.events.push_back(e);
  }
  return s;
}

SavedRound read_round_save(const std::filesystem::path& path) {
  SavedRound s = parse_round_save(read_data_file(path, "saved round", kMaxSaveBytes), path.string());
  s.source = path.string();
  return s;
}

Course saved_course(const Assets& assets, const SavedRound& saved) {
  Course c = load_course(assets, saved.course);
  if (static_cast<std::size_t>(saved.holes) > c.holes.size())
    throw InputError(saved.source + ": holes: " + std::to_string(saved.holes) + " but course '" + saved.course + "' has " +
                     std::to_string(c.holes.size()));
  c.holes.resize(static_cast<std::size_t>(saved.holes));
  try {
    set_up(c, saved.setup);
  } catch (const InputError& e) {
    throw InputError(saved.source + ": " + e.what());
  }
  return c;
}

GolfGroup resume_round(const Assets& assets, const SavedRound& saved) {
  // The group's own refusals (a match of one, skins alone) are the save's "format" and
  // "players" that disagree: said of the file.
  GolfGroup g = [&] {
    const Course course = saved_course(assets, saved);
    try {
      return GolfGroup(assets, course, saved.players, saved.options);
    } catch (const InputError& e) {
      throw InputError(saved.source + ": format \"" + to_string(saved.options.format) + "\" with " +
                       std::to_string(saved.players.size()) + (saved.players.size() == 1 ? " player" : " players") + ": " + e.what());
    }
  }();
  try {
    g.replay(saved.events);
  } catch (const InputError& e) {
    throw InputError(saved.source + ": events: " + e.what());
  }
  return g;
}

}  // namespace sweetspot
