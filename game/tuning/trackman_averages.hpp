// TrackMan's Tour averages (TrackMan 2004-2008 tour averages, DESIGN §4): the reference the
// aero fit (scripts/aero_fit.cpp) and the calibration tests share, written once. Display
// units as published: mph, degrees, rpm, yards.
#pragma once

#include <array>
#include <span>
#include <stdexcept>
#include <string_view>

namespace sweetspot {

/// A row's ball flight: launch (ball speed, launch angle, spin) and what it flies (apex,
/// landing angle, carry). Tour driver: 167 mph, 10.9°, 2686 rpm, 32 yd, 38°, 275 yd.
struct TourFlight {
  const char* club;
  double ball_mph, launch_deg, spin_rpm, apex_yd, landing_deg, carry_yd;
};

/// A row's delivery: club speed (mph) and attack angle (degrees, + up). Tour driver: 113, -1.3.
struct TourSwing {
  const char* club;
  double club_mph, attack_deg;
};

/// PGA Tour, driver to PW; the same clubs in the same order in both tables.
inline constexpr std::array<TourFlight, 12> kPgaTourFlights{{
    {"driver", 167, 10.9, 2686, 32, 38, 275}, {"3-wood", 158, 9.2, 3655, 30, 43, 243},
    {"5-wood", 152, 9.4, 4350, 31, 47, 230},  {"hybrid", 146, 10.2, 4437, 29, 47, 225},
    {"3-iron", 142, 10.4, 4630, 27, 46, 212}, {"4-iron", 137, 11.0, 4836, 28, 48, 203},
    {"5-iron", 132, 12.1, 5361, 31, 49, 194}, {"6-iron", 127, 14.1, 6231, 30, 50, 183},
    {"7-iron", 120, 16.3, 7097, 32, 50, 172}, {"8-iron", 115, 18.1, 7998, 31, 50, 160},
    {"9-iron", 109, 20.4, 8647, 30, 51, 148}, {"pw", 102, 24.2, 9304, 29, 52, 136},
}};
inline constexpr std::array<TourSwing, 12> kPgaTourSwings{{
    {"driver", 113, -1.3}, {"3-wood", 107, -2.9}, {"5-wood", 103, -3.3}, {"hybrid", 100, -3.5},
    {"3-iron", 98, -3.1},  {"4-iron", 96, -3.4},  {"5-iron", 94, -3.7},  {"6-iron", 92, -4.1},
    {"7-iron", 90, -4.3},  {"8-iron", 87, -4.5},  {"9-iron", 85, -4.7},  {"pw", 83, -5.0},
}};

/// LPGA Tour. The table's 3-wood row (2704 rpm at 11.2°, landing 39° from a 23 yd apex) is
/// left out: no model flies that launch that high or steep (a misprint of the spin, likely).
inline constexpr std::array<TourFlight, 10> kLpgaTourFlights{{
    {"driver", 140, 13.2, 2611, 25, 37, 218}, {"5-wood", 128, 12.1, 4501, 26, 43, 185},
    {"7-wood", 123, 12.7, 4693, 25, 46, 174}, {"4-iron", 116, 14.3, 4801, 24, 43, 169},
    {"5-iron", 112, 14.8, 5081, 23, 45, 161}, {"6-iron", 109, 17.1, 5943, 25, 46, 152},
    {"7-iron", 104, 19.0, 6699, 26, 47, 141}, {"8-iron", 100, 20.8, 7494, 25, 47, 130},
    {"9-iron", 93, 23.9, 7589, 26, 47, 119},  {"pw", 86, 25.6, 8403, 23, 48, 107},
}};
/// The LPGA irons' deliveries (the rows the contact model is checked against).
inline constexpr std::array<TourSwing, 7> kLpgaTourIronSwings{{
    {"4-iron", 80, -1.7}, {"5-iron", 79, -1.9}, {"6-iron", 78, -2.3}, {"7-iron", 76, -2.3},
    {"8-iron", 74, -3.1}, {"9-iron", 72, -3.1}, {"pw", 70, -2.8},
}};

/// The row of `club` in `rows`; std::out_of_range when it has none (a programming error:
/// the tables above are fixed).
inline const TourFlight& tour_flight(std::span<const TourFlight> rows, std::string_view club) {
  for (const TourFlight& r : rows)
    if (club == r.club) return r;
  throw std::out_of_range("no TrackMan row for this club");
}

}  // namespace sweetspot
