// Writing scenario text: a quantity with its unit, and a loaded scenario (its document with
// the overrides applied) as TOML that `sweetspot shot FILE` loads back to the same shot.
// Used by the Lab's Save, the only place the window writes text.
#pragma once

#include <string>
#include <vector>

#include "game/content/scenario.hpp"

namespace sweetspot {

/// A number with its unit as scenario text: quantity_text(105, "mph") == "105mph". The
/// shortest digits that read back as the same double, so a value survives the round trip.
std::string quantity_text(double value, const std::string& unit);
/// The decimal a float slider meant: the shortest decimal that is the same float (0.808f ->
/// 0.808, not 0.80800002813).
double float_as_decimal(float value);
/// "[12.5mm, -3mm]".
std::string quantity_list_text(const std::vector<double>& values, const std::string& unit);

/// The scenario's document with the overrides applied, as TOML (sections in schema order,
/// values quoted with units).
std::string scenario_toml(const Scenario& scenario);

}  // namespace sweetspot
