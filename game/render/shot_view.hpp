// How a shot is shown: which world and meshes, whether the ball sat on a tee, where the
// club or bat was at impact. Shared by `sweetspot render`, `play` (window and headless) and
// the game modes, so every view of one shot draws the same scene.
#pragma once

#include <optional>
#include <string>

#include "game/content/scenario.hpp"
#include "game/render/render_command.hpp"
#include "game/render/shot_scene.hpp"
#include "game/core/shot_result.hpp"

namespace sweetspot {

/// The club or bat at impact in its mesh frame, when the shot had one.
std::optional<ImpactorPlacement> impactor_placement(const ShotResult& r);

/// Where the club head or bat is drawn when only launch numbers are known: an illustrative
/// pose, not an impact solve. A club's face touches the back of the ball with its normal
/// along the launch direction (loft ~ launch angle); a bat's sweet spot sits behind the
/// ball, level and square to the launch direction (`bat_length` m, knob on the third-base side).
ImpactorPlacement nominal_impactor(bool bat, const LaunchState& launch, double ball_radius, double bat_length = 0.84);

/// A ball lying still at `centre` (m): the "shot" a view shows while a player addresses it.
ShotTrajectory ball_at_rest(const Vec3& centre);

/// The club a golfer addresses a ball at `centre` with, square behind it along `aim` (unit,
/// horizontal).
ImpactorPlacement club_at_address(const Vec3& centre, const Vec3& aim, double ball_radius);

/// The view of a golfer addressing a full shot at `ball` toward `aim` (unit, horizontal):
/// 9 m behind the ball and 2.6 m up, looking 5° down: his feet at the view's lower edge (16°
/// down of its 20°), the target area a degree or two below the horizon in its upper half.
Camera full_shot_address_camera(const Vec3& ball, const Vec3& aim);

/// The view of a putt at `ball` toward `aim` (unit, horizontal) with the cup `to_pin` m
/// away: 4 m behind and 0.6 m right of the line (aside of the golfer addressing it from
/// the left), 3.2 m up (over his head), looking down the line toward the cup (up to 12.5 m ahead), tilted
/// down as far as it takes to hold the ball no lower than 55 % of the half-height below
/// the image's centre, above the swing meter at the bottom of the window.
Camera putt_address_camera(const Vec3& ball, const Vec3& aim, double to_pin);

/// `c`, a view of a golfer addressing `ball` (his head 1.7 m above it), moved so nothing of
/// `world` (a tree's trunk or crown, a bank) stands between its eye and his head: first
/// brought forward along its own line to just in front of the first thing in the way,
/// still looking down the line he aims along, while that leaves it 3 m or more from him;
/// else swung round him (15° at a time up to side-on, the smallest turn first) to the first
/// line that is clear for 3 m, brought in as far as that line needs, and from there turned
/// back toward his line, the lens widened up to 75°, as far as keeps him and the ball in the
/// picture, so the player still sees where he aims; and where no line is, 2.5 m over his head, a metre or less behind, looking down
/// past him at the ball. Unchanged when the line is clear.
Camera clear_view_of(const Camera& c, const Vec3& ball, const Terrain& world);

ShotSceneInput scene_input_for(const Assets& assets, const ResolvedShot& shot, const ShotResult& r);
RenderRequest render_request_for(const Assets& assets, const ResolvedShot& shot, const ShotResult& r);

}  // namespace sweetspot
