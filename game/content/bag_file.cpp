#include "game/content/bag_file.hpp"

#include <algorithm>

#include "game/content/scenario_toml.hpp"
#include "game/content/toml_file.hpp"
#include "physics/error.hpp"

namespace sweetspot {

Bag load_bag(const Assets& assets, const std::filesystem::path& path, const std::vector<std::string>& skills) {
  const TomlFile f = TomlFile::read(path, "bag");
  f.only_keys(f.root(), "", {"player", "skill", "club"});
  Bag bag;
  bag.player = f.text_or(f.root(), "player", "you");
  std::string skill_names;
  for (const std::string& s : skills) skill_names += (skill_names.empty() ? "" : ", ") + s;
  const toml::node& skill = f.required(f.root(), "skill", "the golfer skill that swung: " + skill_names);
  bag.skill = f.text(skill, "skill");
  if (std::find(skills.begin(), skills.end(), bag.skill) == skills.end())
    f.fail(skill, "skill", "unknown skill '" + bag.skill + "' (allowed: " + skill_names + ")");
  for (const toml::table* t : f.tables(f.root(), "club", true)) {
    f.only_keys(*t, "club", {"name", "carry", "total", "carry_sd", "side_sd", "shots"});
    BagClub c;
    const toml::node& name = f.required(*t, "name", "a club of the equipment (driver ... lw)");
    c.club = f.text(name, "name");
    try {
      assets.equipment().club(c.club);
    } catch (const InputError& e) {
      f.fail(name, "name", e.what());
    }
    if (c.club == "putter") f.fail(name, "name", "the putter has no carry; leave it out");
    for (const BagClub& other : bag.clubs)
      if (other.club == c.club) f.fail(name, "name", "'" + c.club + "' is in the bag twice");
    c.carry = f.quantity(f.required(*t, "carry", "the mean carry, e.g. \"150m\""), "carry", Dimension::Length, &BagClub::kCarry);
    const toml::node& total = f.required(*t, "total", "the mean total, e.g. \"160m\"");
    c.total = f.quantity(total, "total", Dimension::Length, &BagClub::kDistance);
    if (c.total < c.carry) f.fail(total, "total", "shorter than the carry");
    c.carry_sd = f.quantity_or(*t, "carry_sd", Dimension::Length, 0.0, &BagClub::kDistance);
    c.side_sd = f.quantity_or(*t, "side_sd", Dimension::Length, 0.0, &BagClub::kDistance);
    if (const toml::node* n = t->get("shots")) c.shots = f.whole_number(*n, "shots", BagClub::kShots);
    bag.clubs.push_back(c);
  }
  std::stable_sort(bag.clubs.begin(), bag.clubs.end(), [](const BagClub& a, const BagClub& b) { return a.carry > b.carry; });
  return bag;
}

std::string bag_toml(const Bag& bag) {
  std::string out = "# A bag measured at the range: mean carry and total, spreads (one standard deviation).\n";
  // Names are written inside TOML basic strings: quotes, backslashes and controls are dropped.
  auto plain = [](std::string t) {
    t.erase(std::remove_if(t.begin(), t.end(), [](char ch) { return ch == '"' || ch == '\\' || static_cast<unsigned char>(ch) < 0x20; }),
            t.end());
    return t;
  };
  out += "player = \"" + plain(bag.player) + "\"\nskill = \"" + plain(bag.skill) + "\"\n";
  for (const BagClub& c : bag.clubs) {
    out += "\n[[club]]\nname = \"" + c.club + "\"\n";
    out += "carry = \"" + quantity_text(c.carry, "m") + "\"\n";
    out += "total = \"" + quantity_text(std::max(c.total, c.carry), "m") + "\"\n";
    out += "carry_sd = \"" + quantity_text(c.carry_sd, "m") + "\"\n";
    out += "side_sd = \"" + quantity_text(c.side_sd, "m") + "\"\n";
    if (c.shots > 0) out += "shots = " + std::to_string(c.shots) + "\n";
  }
  return out;
}

}  // namespace sweetspot
