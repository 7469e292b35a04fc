// A course's own metric frame (DESIGN §2): x east, z south, y up, metres from an origin near
// the course's centre. Over the kilometre or two a course spans, a local projection is exact
// to a millimetre: each point's east offset is taken along its own parallel (the WGS84
// prime-vertical radius at its latitude) and its north offset along the meridian (the
// meridional radius), so meridians converge as they do on the ellipsoid.
#pragma once

#include "game/courses/golf_map.hpp"

namespace sweetspot {

struct LocalPoint {
  double x = 0.0, z = 0.0;  ///< m east, m south of the frame's origin
};

class LocalFrame {
 public:
  explicit LocalFrame(const GeoPoint& origin) : origin_(origin) {}
  /// The frame centred on the middle of everything `map` draws.
  static LocalFrame around(const GolfMap& map);
  LocalPoint to_local(const GeoPoint& p) const;
  /// The inverse of to_local (to a micrometre: three fixed-point steps on the latitude).
  GeoPoint to_geo(const LocalPoint& p) const;
  const GeoPoint& origin() const { return origin_; }

 private:
  GeoPoint origin_;
};

}  // namespace sweetspot
