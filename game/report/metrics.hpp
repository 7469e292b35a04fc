// Launch-monitor metrics, each defined once: its id, the table label, the CSV column and
// how to read it from a ShotResult in display units. A sport's profile lists which ids its
// table and CSV show (assets/sports.toml), so the table, the CSV and the window's
// launch-monitor panel stay in step. Adding a metric: one entry in metrics.cpp, then name
// it in a sport's `report` or `csv` list.
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "game/core/shot_result.hpp"

namespace sweetspot {

enum class UnitSystem { Imperial, Metric };
/// "imperial" / "metric"; anything else -> InputError naming `flag` and the choices.
UnitSystem parse_unit_system(std::string_view text, std::string_view flag = "--units");

/// How quantities are shown: the unit system and, for distances in imperial, the sport's
/// unit (golf "yd", baseball "ft").
struct DisplayUnits {
  UnitSystem system = UnitSystem::Imperial;
  std::string distance = "yd";

  bool imperial() const { return system == UnitSystem::Imperial; }
  const char* speed_unit() const { return imperial() ? "mph" : "m/s"; }
  double speed(double mps) const;
  const char* distance_unit() const { return imperial() ? distance.c_str() : "m"; }
  double dist(double m) const;
};

struct Metric {
  std::string_view id;        ///< "ball_speed"
  std::string_view label;     ///< table label, "Ball speed"
  /// The row's text ("167.0 mph"), or nothing when the shot has no such number (no impact).
  std::function<std::optional<std::string>(const ShotResult&, const DisplayUnits&)> show;
  /// CSV column name in these units ("ball_speed_mph").
  std::function<std::string(const DisplayUnits&)> csv_name;
  /// CSV cell (empty when not applicable).
  std::function<std::string(const ShotResult&, const DisplayUnits&)> csv_value;
  /// The number behind the row in display units and its unit, for plots and the panel's
  /// reference column; nothing for text rows.
  std::function<std::optional<double>(const ShotResult&, const DisplayUnits&)> number;
  std::string_view expect;    ///< the scenario's expect.* key this row is compared with ("" = none)
};

/// The batting convention's collision efficiency q = (exit − bat)/(pitch + bat) (Nathan;
/// Statcast): EV = q·pitch + (1 + q)·bat. Good contact on a wood bat ~0.2. 0 with no closing speed.
double collision_efficiency(const ShotResult& r);

/// The metric with that id, or nullptr.
const Metric* find_metric(std::string_view id);
/// Every id, for messages.
std::string metric_ids();

/// Launch-monitor table: a title line, then "Label  value" for each of `rows` the shot has.
std::string metric_table(const std::string& title, const std::vector<std::string>& rows, const ShotResult& r,
                         const DisplayUnits& u);

}  // namespace sweetspot
