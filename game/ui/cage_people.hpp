// The batting cage's people in its 3D scene (issue 44): the pitcher's wind-up, release and
// follow-through, the batter's stride, swing and follow-through, and the eight fielders where
// they stand or on the runs field_play gave them. Lit boxes the renderer shades and shadows
// like the rest of the park, so a clip of the play (F10) has them too.
#pragma once

#include <Eigen/Core>

#include "game/modes/baseball/cage.hpp"
#include "game/modes/baseball/figures.hpp"
#include "game/render/shot_scene.hpp"

namespace sweetspot {

/// A limb is drawn at least this many pixels wide, a head twice that: a fielder 100 m out is
/// ~2 px a limb at true size from the batter's eye.
inline constexpr double kFigureMinPx = 2.5;

/// The people as the cage stands at mode time `now`, on the scene's clock: while a pitch
/// flies t is its pitch clock (BattingCage::pitch_clock), after contact the seconds since
/// (BattingCage::batted_at); between pitches they hold as they are at `now`.
PeopleFn cage_people(const BattingCage& cage, double now);

/// The scene time at mode time `now` on the clock cage_people's figures keep.
double cage_scene_time(const BattingCage& cage, double now);

/// One figure's bones as boxes (`width` m, at least kFigureMinPx on screen), its head a
/// block, its bat thinner in `bat`.
void append_figure(MeshData& out, const Figure& f, const PeopleFrame& frame, const Eigen::Vector3f& body,
                   const Eigen::Vector3f& bat);

}  // namespace sweetspot
