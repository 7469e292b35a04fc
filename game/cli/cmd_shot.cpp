// `sweetspot shot SCENARIO`: one shot, printed as a launch-monitor table (default), the
// DESIGN §6 JSON, a GSPro OpenConnect v1 message or a CSV row.
#include <algorithm>
#include <cctype>
#include <filesystem>
#include <iostream>
#include <memory>

#include <nlohmann/json.hpp>

#include "game/cli/command.hpp"
#include "game/modes/lab/grip.hpp"
#include "game/report/impact_sound.hpp"
#include "game/report/report.hpp"
#include "game/content/scenario.hpp"
#include "game/net/session_file.hpp"
#include "game/util/atomic_file.hpp"
#include "physics/error.hpp"
#include "game/rules/run_shot.hpp"

namespace sweetspot::cli {
namespace {

struct ShotOptions {
  std::string scenario;
  std::string e, mu;
  std::vector<std::string> sets;
  bool json = false, gspro = false, csv = false;
  std::string units = "imperial";
  int shot_number = 0;       // 0: 1, or the session's next
  std::string session;       // a JSON-lines file the message is appended to
  std::string sound;         // a WAV file for the strike's sound
};

constexpr int kMaxShotNumber = 1000000000;

// The highest ShotNumber among the session file's lines (0 for a missing or empty file).
// A line that is not an Open Connect message is refused with its file:line: appending to a
// file we cannot read would number the shot wrongly and break `sweetspot send`.
int last_shot_number(const SessionFile& f, const std::string& path) {
  int last = 0;
  for (const auto& [number, j] : f.lines) {
    const auto n = j.find("ShotNumber");
    if (n == j.end() || !n->is_number_integer() || n->get<long long>() < 0 || n->get<long long>() > kMaxShotNumber)
      throw InputError(path + ":" + std::to_string(number) +
                       ": not an Open Connect shot line with a ShotNumber in [0, 1000000000] (--session appends to "
                       "files it wrote)");
    last = std::max(last, n->get<int>());
  }
  return last;
}

RunFn setup_shot(CLI::App& sub) {
  auto o = std::make_shared<ShotOptions>();
  sub.add_option("scenario", o->scenario, "built-in name (see `sweetspot list`) or a .toml file")->required();
  sub.add_option("--e", o->e, "normal restitution override, 0..1 (= --set impact.e=X)");
  sub.add_option("--mu", o->mu, "friction coefficient override, >= 0 (= --set impact.mu=X)");
  sub.add_option("--set", o->sets, "override any scenario key: key=value, e.g. swing.speed=105mph")
      ->type_name("KEY=VALUE");
  auto* json = sub.add_flag("--json", o->json, "print the DESIGN §6 JSON object");
  auto* gspro = sub.add_flag("--gspro", o->gspro, "print a GSPro OpenConnect v1 shot message");
  auto* csv = sub.add_flag("--csv", o->csv, "print a CSV header and row (Statcast names for baseball)");
  json->excludes(gspro)->excludes(csv);
  gspro->excludes(csv);
  auto* number = sub.add_option("--shot-number", o->shot_number, "--gspro: the message's ShotNumber, 1..1000000000 (default 1, or the session's next)")
      ->check(int_range<int>(1, kMaxShotNumber));
  auto* session = sub.add_option("--session", o->session,
                                 "--gspro: append the message as one line to this JSON-lines file, numbered after its "
                                 "last shot (replay it with `sweetspot send`)");
  number->needs(gspro);
  session->needs(gspro);
  sub.add_option("--sound", o->sound, "also write the strike's sound (synthesised from the impact) to this WAV file, 48 kHz mono");
  sub.add_option("--units", o->units, "display units of the table and CSV: imperial or metric")
      ->capture_default_str();
  return [o](const Assets& assets) -> int {
    const UnitSystem units = parse_unit_system(o->units);
    // --e / --mu are --set shorthands; their messages name the flag itself.
    ScenarioDoc doc = read_toml_doc(resolve_scenario(assets, o->scenario));
    for (const auto& s : o->sets) apply_set(doc, s);
    if (!o->e.empty()) apply_set(doc, "impact.e=" + o->e, "--e " + o->e);
    if (!o->mu.empty()) apply_set(doc, "impact.mu=" + o->mu, "--mu " + o->mu);
    const Scenario scenario = scenario_from_doc(assets, doc, o->scenario);
    if (!o->sound.empty()) {
      check_output_path(o->sound, "--sound");
      std::string ext = std::filesystem::path(o->sound).extension().string();
      for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
      if (ext != ".wav") throw InputError("--sound " + o->sound + ": the sound is a WAV file; name it FILE.wav");
    }
    ShotResult r = run_scenario(scenario, RunOptions{true, false});
    if (!o->sound.empty()) write_impact_wav(r, o->sound, "--sound");
    if (r.impact.present) r.impact.mu_grip = mu_grip(scenario.resolved);
    const SportProfile& sport = *scenario.resolved.sport;
    if (o->json) {
      std::cout << json_text(shot_json(r)) << "\n";
    } else if (o->gspro) {
      const SessionFile session = o->session.empty() ? SessionFile{}
                                                     : read_session_file(o->session, "--session appends to files it wrote");
      const int last = last_shot_number(session, o->session);
      if (!o->session.empty() && o->shot_number > 0 && o->shot_number <= last)
        throw InputError("--shot-number " + std::to_string(o->shot_number) + ": " + o->session + " already holds shot " +
                         std::to_string(last) + "; a session's numbers rise (leave --shot-number out for " +
                         std::to_string(last + 1) + ")");
      const int number = o->shot_number > 0 ? o->shot_number : last + 1;
      if (number > kMaxShotNumber)
        throw InputError(o->session + ": the session is full (ShotNumber would pass 1000000000)");
      const nlohmann::json message = gspro_json(r, number);
      if (!o->session.empty()) write_file_atomic(o->session, session.text + json_text(message, -1) + "\n", OverInput::Allow);
      std::cout << json_text(message) << "\n";
    } else if (o->csv) {
      std::cout << csv_header(sport, units) << csv_row(r, sport, units);
    } else {
      std::cout << launch_table(r, sport, units);
    }
    return 0;
  };
}

const CommandRegistrar shot_command{20, "shot", "simulate one scenario: launch-monitor table, --json, --gspro or --csv", setup_shot};

}  // namespace
}  // namespace sweetspot::cli
