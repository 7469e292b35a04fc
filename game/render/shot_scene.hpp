// Builds the Scene of one shot (DESIGN §7): sky, lit terrain from the world OBJ, the ball
// at time t, the trail coloured by phase, landing and rest markers, distance markers (every
// 50 yd for golf, the fence distances for baseball), the tee and flag, and the club or bat
// at impact. Owns the GPU meshes it loads, so it needs a current GL context.
#pragma once

#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <tuple>
#include <vector>

#include "game/render/camera.hpp"
#include "game/render/scene.hpp"
#include "physics/math.hpp"
#include "game/content/world_asset.hpp"
#include "game/content/assets.hpp"
#include "physics/trajectory.hpp"

namespace sweetspot {

/// The flagstick's height: 2.13 m (7 ft, the usual height; the Rules set none), as
/// assets/meshes/flag.obj models it.
inline constexpr double kFlagstickHeight = 2.13;  // m

/// An arrow lying on the ground (a green's downhill), drawn in the scene so the people and
/// the ground in front of it hide it as they hide the turf.
struct GroundArrow {
  Vec3 from = Vec3::Zero(), to = Vec3::Zero();  ///< m, on the ground
  Eigen::Vector3f color = Eigen::Vector3f::Ones();
};

/// Where the club head or bat is at impact: its mesh frame (HEAD FRAME / BAT FRAME) to
/// world. Fill it from Delivery::impactor_at_impact (position, orientation).
struct ImpactorPlacement {
  Vec3 position = Vec3::Zero();          ///< m, mesh-frame origin in the world
  Quat orientation = Quat::Identity();   ///< mesh frame -> world
  /// m/s, the head's (or the bat's contact point's) velocity at impact: the club path and
  /// attack angle drawn through the ball (~50 m/s for a tour driver); zero = not known.
  Vec3 velocity = Vec3::Zero();
};

/// The moment and the view a scene's people are drawn for: the scene's clock (s; what
/// build() was given) and its camera, so a figure far away can keep a few pixels of width.
struct PeopleFrame {
  double t = 0.0;
  const Camera* camera = nullptr;
  int height = 0;  ///< px of the image
};
/// Appends the people on the field at a moment, as lit boxes (golfer_figure.hpp's
/// append_limb), to `out`. Copied with the scene's input onto a clip's own thread: it must
/// hold what it draws by value.
using PeopleFn = std::function<void(const PeopleFrame& frame, MeshData& out)>;

struct ShotSceneInput {
  const Assets* assets = nullptr;       ///< required: where the meshes are
  const WorldAsset* world = nullptr;    ///< the world drawn and asked for heights; nullptr = a grass plane
  /// "yd" or "m": stripes across the hole every 50 of them (golf); "ft": the fence distances
  /// (baseball). Labels read in the same unit.
  std::string distance_unit = "yd";
  double ball_radius = 0.021335;  ///< m (golf 0.021335, baseball 0.0369)
  bool tee = false;               ///< draw a tee under the launch point (the ball was teed up)
  std::optional<ImpactorPlacement> impactor;
  /// assets/meshes name or a path ("driver_head", "iron_head", "putter_head", "bat"); "" = none.
  std::string impactor_mesh;
  /// Flag position (m); nothing = the world's pin, if it has one.
  std::optional<Vec3> flag;
  /// The tee box's markers (m, on the ground) and their colour: the tee set's.
  std::vector<std::pair<Vec3, Eigen::Vector3f>> tee_markers;
  /// m/s, world, horizontal: the flag streams downwind and flutters with it.
  Vec3 wind = Vec3::Zero();
  /// unit, horizontal: the line the shot was aimed down (aim_line of ShotResult::aim); the
  /// Behind, Side and Top cameras look along it. A range's and a ballpark's is +x.
  Vec3 target_line = Vec3::UnitX();
  /// The players the mode puts on the field (a batting cage's pitcher, batter and
  /// fielders); empty = none. The golfer comes with his club (set_shot, set_address).
  PeopleFn people;
};

/// Sizes of the screen-constant decorations, in pixels of the output image.
struct SceneStyle {
  double trail_width_px = 5.0;
  double trail_glow_px = 18.0;      ///< the tracer's soft halo (0 = none)
  bool legend = true;               ///< the trail colours' key in the image's bottom-left corner
  double ball_min_radius_px = 4.0;  ///< the ball is drawn at least this big (true size is sub-pixel far away)
  double label_height_px = 16.0;
  double marker_radius_px = 11.0;
  /// The club head or bat is drawn at least this big (px, its longest extent): from a TV
  /// distance a real 12 cm head is a few pixels. It grows about the ball's centre, with the
  /// ball, so the strike keeps its geometry.
  double impactor_min_px = 28.0;
};

class ShotScene {
 public:
  /// Loads the world and equipment meshes. Throws InputError for an unknown world, mesh or
  /// sport, RenderError for an unreadable mesh file.
  explicit ShotScene(const ShotSceneInput& input, const SceneStyle& style = {});
  ~ShotScene();
  ShotScene(const ShotScene&) = delete;
  ShotScene& operator=(const ShotScene&) = delete;

  /// The replay's pre-roll (s) that shows the downswing before launch: 0 without a club or
  /// bat velocity.
  double pre_roll() const;
  /// Replaces the shot (the game recomputes it whenever a parameter changes).
  void set_shot(const ShotTrajectory& trajectory, const std::optional<ImpactorPlacement>& impactor);
  /// The horizontal direction the golf distance lines run along from the ball's start
  /// (every 50 yd, across it). Nothing = the shot's own direction (launch to rest), or +x
  /// (the world's target line) for a ball that did not move. The golf game sets the
  /// player's aim while the ball waits to be hit.
  void set_aim(const std::optional<Vec3>& aim) { aim_ = aim; }
  /// The club at address behind a ball that waits to be hit (nothing: none): drawn with the
  /// golfer holding it, square to the shot. A shot with its own club (set_shot) shows that.
  void set_address(const std::optional<ImpactorPlacement>& club) { address_ = club; }
  /// How far the golfer at address has wound his backswing, 0 (at the ball) to 1 (the top):
  /// the meter's marker as it climbs and comes back down, so the club follows the player's
  /// clicks. The club moves up the arc its downswing comes down (swing_pose.hpp).
  void set_backswing(double fraction) { backswing_ = fraction < 0.0 ? 0.0 : fraction > 1.0 ? 1.0 : fraction; }
  /// The distance (m from the ball) the player means to play, e.g. his club's carry: the
  /// golf stripes' numbers nearest it are written first, so where the far stripes crowd
  /// together the one that matters is the one shown. Nothing: nearest the ball first.
  void set_focus(const std::optional<double>& metres) { focus_ = metres; }
  /// Whether the landing ring is labelled with the carry (on by default): a ground ball's
  /// first hop a few feet out says nothing of it, and beside the label where it was fielded
  /// it reads as a second distance for one ball.
  void set_carry_label(bool shown) { carry_label_ = shown; }
  /// Whether the golf stripes carry their numbers (on by default): a range whose flags say
  /// their distances would show each twice, the numbers crowding the target area.
  void set_stripe_numbers(bool shown) { stripe_numbers_ = shown; }
  /// Words before the carry's number ("landed 266 ft"): beside a second distance for the
  /// same ball (where a batted ball was fielded) a bare number does not say which is which.
  /// Empty (the default): the number alone, as a golf trail's ring reads.
  void set_carry_words(std::string words) { carry_words_ = std::move(words); }
  /// Words before the rest pin's number when no rest label is set ("fielded 266 ft").
  void set_rest_words(std::string words) { rest_words_ = std::move(words); }
  /// The rest pin's label: nothing = the total distance, as the carry's; "" = none; else the
  /// text given (a putt's "6 ft to the cup": beside the cup the total reads as what is left).
  void set_rest_label(std::optional<std::string> text) { rest_label_ = std::move(text); }
  /// Arrows on the ground (none: none), e.g. a green's slopes while a putt is lined up.
  void set_ground_arrows(std::vector<GroundArrow> arrows) { arrows_ = std::move(arrows); }
  /// ShotSceneInput::wind, ::people and ::target_line, as play goes on.
  void set_wind(const Vec3& wind);
  void set_target_line(const Vec3& line);
  void set_people(PeopleFn people);
  const ShotTrajectory& trajectory() const { return trajectory_; }
  /// What the scene was made of; with trajectory() and impactor(), enough to make it again
  /// elsewhere (a clip rendered off-screen on another thread).
  const ShotSceneInput& input() const;
  const std::optional<ImpactorPlacement>& impactor() const { return impactor_; }

  /// The camera of `kind` at time t (s) for a width x height image, its eye kept above
  /// the ground (keep_above_ground).
  Camera camera(CameraKind kind, double t, int width, int height, const FrameWindow& window = {}) const;
  /// `c` with its eye raised, if needed, to `clearance` m above the ground under it (the
  /// world's, or the surrounding plane's), the target kept: a mouse orbit or a framing
  /// never looks from under the turf.
  Camera keep_above_ground(Camera c, double clearance = 1.0) const;
  /// `c` with a clear view of `subject` (the ball) past the trees: where a crown stands between
  /// them, the eye rises about the ball at the same distance, as a broadcast's tower camera
  /// looks over the trees (the lowest clear view up to 80 deg down); where no height clears
  /// it (a ball under a canopy), the eye comes in to stand in front of the first tree between
  /// them, so it looks at the ball, not at the inside of a crown. Only trees: ground between
  /// them is keep_above_ground's.
  Camera keep_clear_of_trees(Camera c, const Vec3& subject) const;
  /// How far the side view looks down (rad) on `framing`'s shot for a width x height image:
  /// its usual 10°, or steeper, up to 60°, until no more than a tenth of the flight is
  /// behind a tree (a side view from 200 m off the line of a fairway between rows of trees
  /// sees the crowns, not the ball). Kept for the shot: the side view does not move with t.
  double side_down(const ShotFraming& framing, int width, int height) const;
  /// Everything to draw at time t (s; clamped to the shot) seen by `camera`. A negative t
  /// is the pre-roll: the ball waits at launch and the club or bat comes down its swing.
  Scene build(const Camera& camera, double t, int width, int height) const;

  /// Ground height (m) under (x, z): the physics world's support query, if any ground
  /// covers it.
  std::optional<double> ground_height(double x, double z) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
  ShotTrajectory trajectory_;
  std::optional<ImpactorPlacement> impactor_;
  std::optional<Vec3> aim_;
  std::optional<ImpactorPlacement> address_;
  double backswing_ = 0.0;
  std::vector<GroundArrow> arrows_;
  std::optional<double> focus_;
  bool carry_label_ = true;
  bool stripe_numbers_ = true;
  /// side_down() for the shot and image size it was found for.
  mutable std::optional<std::tuple<int, int, double>> side_down_;
  std::string carry_words_, rest_words_;
  std::optional<std::string> rest_label_;
};

}  // namespace sweetspot
