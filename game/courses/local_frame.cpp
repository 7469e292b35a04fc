#include "game/courses/local_frame.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "physics/error.hpp"

namespace sweetspot {
namespace {
constexpr double kA = 6378137.0;               // m, WGS84 semi-major axis
constexpr double kE2 = 6.69437999014e-3;       // WGS84 first eccentricity squared
constexpr double kRad = 3.14159265358979323846 / 180.0;
}  // namespace

LocalFrame LocalFrame::around(const GolfMap& map) {
  double lat0 = std::numeric_limits<double>::infinity(), lat1 = -lat0, lon0 = lat0, lon1 = -lat0;
  const auto take = [&](const GeoPoint& p) {
    lat0 = std::min(lat0, p.lat);
    lat1 = std::max(lat1, p.lat);
    lon0 = std::min(lon0, p.lon);
    lon1 = std::max(lon1, p.lon);
  };
  for_each_point(map, take);
  if (!std::isfinite(lat0)) throw InputError("the map draws nothing to place a course on");
  return LocalFrame({0.5 * (lat0 + lat1), 0.5 * (lon0 + lon1)});
}

LocalPoint LocalFrame::to_local(const GeoPoint& p) const {
  // Meridian arc from the origin's latitude: the meridional radius at the mid-latitude is
  // exact to (Δφ)² of it, below a millimetre over a few kilometres.
  const double mid = 0.5 * (p.lat + origin_.lat) * kRad;
  const double s_mid = std::sin(mid);
  const double meridional = kA * (1.0 - kE2) / std::pow(1.0 - kE2 * s_mid * s_mid, 1.5);
  const double s = std::sin(p.lat * kRad);
  const double prime_vertical = kA / std::sqrt(1.0 - kE2 * s * s);
  const double east = (p.lon - origin_.lon) * kRad * prime_vertical * std::cos(p.lat * kRad);
  const double north = (p.lat - origin_.lat) * kRad * meridional;
  return {east, -north};
}

GeoPoint LocalFrame::to_geo(const LocalPoint& p) const {
  GeoPoint g{origin_.lat, origin_.lon};
  for (int i = 0; i < 4; ++i) {
    const double mid = 0.5 * (g.lat + origin_.lat) * kRad;
    const double s_mid = std::sin(mid);
    const double meridional = kA * (1.0 - kE2) / std::pow(1.0 - kE2 * s_mid * s_mid, 1.5);
    g.lat = origin_.lat + (-p.z) / meridional / kRad;
  }
  const double s = std::sin(g.lat * kRad);
  const double prime_vertical = kA / std::sqrt(1.0 - kE2 * s * s);
  g.lon = origin_.lon + p.x / (prime_vertical * std::cos(g.lat * kRad)) / kRad;
  return g;
}

}  // namespace sweetspot
