// Shot reports for people and programs: a launch-monitor table in display units, the
// DESIGN §6 JSON, a GSPro OpenConnect v1 shot message and CSV rows (Statcast column
// names for baseball). All read a ShotResult; none computes physics.
#pragma once

#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

#include "game/core/shot_result.hpp"
#include "game/core/sport.hpp"
#include "game/report/metrics.hpp"

namespace sweetspot {

/// The display units of a sport in a unit system.
DisplayUnits display_units(const SportProfile& sport, UnitSystem units);

/// Refuses (InputError at sports.toml's line) a report or csv metric id the build does not know.
void check_metric_ids(const SportProfile& sport);

/// Launch-monitor table: one "Label  value unit" line per row of the sport's profile.
std::string launch_table(const ShotResult& r, const SportProfile& sport, UnitSystem units);

/// DESIGN §6 object: scenario, sport, launch{...}, impact{...} (when the shot had an
/// impact), flight{...}. SI throughout; key names are a contract.
nlohmann::json shot_json(const ShotResult& r);

/// GSPro Open Connect API v1 shot message (golf; baseball sends the same ball fields).
/// Units as GSPro expects with "Units": "Yards": mph, degrees, rpm, yards; face impact
/// offsets in millimetres; closure rate in deg/s.
/// JSON as text for output (indent -1 = compact). Strings that are not UTF-8 (a file name in
/// another encoding) have their bad bytes replaced by U+FFFD instead of failing the write.
std::string json_text(const nlohmann::json& j, int indent = 2);
nlohmann::json gspro_json(const ShotResult& r, int shot_number = 1);

/// CSV header and one row: the sport profile's csv columns. Baseball uses Statcast names
/// and units (launch_speed mph, launch_angle, hit_distance_sc ft, ...); golf columns carry
/// their unit in the name and follow `units`.
std::string csv_header(const SportProfile& sport, UnitSystem units);
std::string csv_row(const ShotResult& r, const SportProfile& sport, UnitSystem units);

/// Quotes a CSV field when it holds a comma, quote or newline (RFC 4180).
std::string csv_field(std::string_view text);

}  // namespace sweetspot
