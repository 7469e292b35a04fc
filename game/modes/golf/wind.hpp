// The wind on each hole of a round: the course's own where it states one, else drawn from
// the round's seed, so a round replays with the same wind and two rounds differ.
#pragma once

#include <cstdint>
#include <vector>

#include "game/content/course_file.hpp"
#include "game/modes/golf/round.hpp"

namespace sweetspot {

/// Surface wind speeds follow a Weibull distribution of shape ~2, a Rayleigh distribution
/// (Justus, Hargraves & Yalcin 1976, "Nationwide assessment of potential output from
/// wind-powered generators", J. Appl. Meteor. 15); a mean of 4 m/s at 10 m is a typical
/// open inland site (NREL's 10 m wind maps: 3.5–5 m/s over most of the US). Drawn speeds
/// are capped at 12 m/s, where golf is still played.
inline constexpr double kMeanWind = 4.0;   // m/s at 10 m
inline constexpr double kMaxDrawnWind = 12.0;  // m/s

/// One wind per hole: the hole's stated wind, or a seeded draw (direction uniform).
std::vector<HoleWind> round_winds(const Course& course, std::uint64_t seed);

}  // namespace sweetspot
