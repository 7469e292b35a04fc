#include "game/render/shot_scene.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "game/render/ballpark_dressing.hpp"
#include "game/render/gpu_mesh.hpp"
#include "game/render/legend.hpp"
#include "game/render/mesh_import.hpp"
#include "game/render/overlay_geometry.hpp"
#include "game/render/render_paths.hpp"
#include "game/render/golfer_figure.hpp"
#include "game/render/swing_pose.hpp"
#include "game/render/trail_geometry.hpp"
#include "physics/error.hpp"

namespace sweetspot {
namespace {

// A course's tiles: 100 m squares, a few dozen over 18 holes' ~1 km, each a handful of draws
// of its own; small enough that a view down one hole leaves most of them out.
constexpr float kWorldTile = 100.0f;  // m
// Far tiles draw coarser (cluster_vertices). A cell of c m at d m spans c/d rad of an 800 px,
// 45° view (~1000 px a radian): 1.5 m from 200 m is ~8 px, so a green, meshed every 0.5 m for its putts, is a few
// hundred triangles from the next tee instead of thousands. Beyond 450 m the cells pass the
// terrain's own 8 m grid (12 m, then 24 m from 900 m): edges between surfaces step by tens of
// pixels there, under the haze, which is the price of the golf window's 20 ms frame on
// llvmpipe (docs/performance.md).
struct FarLevel {
  float from, cell;  // m
};
constexpr std::array<FarLevel, 3> kFarLevels{{{200.0f, 1.5f}, {450.0f, 12.0f}, {900.0f, 24.0f}}};

// Where the golfer holds a club, in its HEAD FRAME: up the shaft from the hosel
// (scripts/gen_meshes.py: the driver's at (-12, 18, -50) mm with a 58° lie, the iron's at
// (-8, 14.4, -36) mm and 62°, the putter's at (-4, 15, -37.5) mm and 70°) by the club's
// length: a driver 45 in, a 7-iron 37 in, a putter 34 in (the common men's lengths; the Rules
// cap a club at 48 in, putters excepted). The head's mesh carries only the shaft's lower part.
struct ClubGrip {
  Vec3 hosel, axis;
  double length;
};
ClubGrip club_grip(const std::string& mesh) {
  const auto axis = [](double back, double lie_deg) {
    return Vec3(back, std::sin(deg_to_rad(lie_deg)), -std::cos(deg_to_rad(lie_deg))).normalized();
  };
  if (mesh == "driver_head") return {Vec3(-0.012, 0.018, -0.050), axis(-0.05, 58.0), 45.0 * 0.0254};
  if (mesh == "putter_head") return {Vec3(-0.004, 0.015, -0.0375), axis(-0.02, 70.0), 34.0 * 0.0254};
  return {Vec3(-0.008, 0.0144, -0.036), axis(-0.05, 62.0), 37.0 * 0.0254};
}

// The golfer holding the club at `pose` (its impact pose `impact`: where he stands), facing
// along `target`, with the shaft and grip the head's mesh lacks.
void add_golfer(Scene& scene, const std::string& mesh, const ImpactorPlacement& pose, const ImpactorPlacement& impact,
                Vec3 target, double ground_y) {
  const ClubGrip c = club_grip(mesh);
  const Vec3 grip_head = c.hosel + c.length * c.axis;  // the hands, in the head's frame
  const Vec3 grip0 = impact.position + impact.orientation * grip_head;
  const Vec3 grip = pose.position + pose.orientation * grip_head;
  target.y() = 0.0;
  if (target.norm() < 1e-6) target = Vec3::UnitX();
  append_golfer(scene.figures, golfer_body(grip, grip0, target.normalized(), ground_y));
  append_club_shaft(scene.figures, grip, pose.orientation * c.axis, c.length);
}

// A golfer ~1.8 m tall reads as a person swinging from ~40 px (ESTIMATE: a figure a
// twentieth of an 800 px view, as a TV wide shot shows a player down the fairway): that
// close he is drawn with the club at true size in his hands; farther a magnified club shows
// the strike instead (a figure of a few pixels would be a smudge, a club with no one
// holding it floats).
constexpr double kGolferHeight = 1.8, kGolferReadsPx = 40.0;

constexpr double kYard = 0.9144;  // m
constexpr double kFoot = 0.3048;  // m

const Eigen::Vector3f kWhite{1.0f, 1.0f, 1.0f};
const Eigen::Vector3f kLandingColor{0.10f, 0.90f, 1.00f};
const Eigen::Vector3f kRestColor{1.00f, 1.00f, 1.00f};
const Eigen::Vector3f kFenceLabelColor{1.00f, 0.92f, 0.30f};
const Eigen::Vector3f kShadowColor{0.05f, 0.07f, 0.05f};
const Eigen::Vector3f kTrackColor{0.10f, 0.22f, 0.08f};
const Eigen::Vector3f kBallShadowColor{0.06f, 0.11f, 0.05f};
const Eigen::Vector3f kPathColor{0.55f, 0.95f, 1.00f};  // club path (with attack angle)
const Eigen::Vector3f kFaceColor{1.00f, 0.30f, 0.25f};  // face normal

Eigen::Matrix4f translate_scale(const Vec3& p, double s) {
  Eigen::Matrix4f m = Eigen::Matrix4f::Identity();
  m.block<3, 3>(0, 0) *= static_cast<float>(s);
  m.block<3, 1>(0, 3) = p.cast<float>();
  return m;
}

// The scene's distance unit: metres per unit and its symbol ("yd" and "m" golf, "ft" baseball).
double unit_length(const std::string& unit) { return unit == "yd" ? kYard : unit == "ft" ? kFoot : 1.0; }

std::string format_distance(double metres, const std::string& unit) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.0f %s", metres / unit_length(unit), unit.c_str());
  return buf;
}

// A golf ball's carry or run as a player reads it: yards (or metres) for a shot, feet (or
// metres to the decimetre) when the whole shot (`scale`, m) is under 20 m, as the HUD's putts
// and tap-ins read.
std::string format_golf_distance(double metres, const std::string& unit, double scale) {
  constexpr double kShort = 20.0;  // m
  if (scale >= kShort) return format_distance(metres, unit);
  char buf[32];
  if (unit == "m") std::snprintf(buf, sizeof buf, "%.1f m", metres);
  else std::snprintf(buf, sizeof buf, "%.0f ft", metres / kFoot);
  return buf;
}

MeshData grass_plane(double y, double half, const char* material) {
  MeshData m;
  const auto p = palette_color(material);
  for (const Vec3& q : {Vec3(-half, y, -half), Vec3(half, y, -half), Vec3(half, y, half), Vec3(-half, y, half)}) {
    Vertex v;
    v.position = q.cast<float>();
    v.normal = Eigen::Vector3f::UnitY();
    v.color = p->color;
    v.pattern = p->pattern;
    m.vertices.push_back(v);
  }
  m.indices = {0, 1, 2, 0, 2, 3};
  return m;
}

}  // namespace

struct ShotScene::Impl {
  ShotSceneInput input;
  SceneStyle style;
  bool golf = true;
  // The world in ground tiles, each with its box, so that a view draws only the tiles it
  // sees (a course is one mesh of every hole: ~160k triangles for 18).
  struct Tile {
    std::unique_ptr<GpuMesh> mesh;
    std::array<std::unique_ptr<GpuMesh>, kFarLevels.size()> far;  ///< coarser for farther (kFarLevels)
    Eigen::AlignedBox3f box;
  };
  std::vector<Tile> world;
  std::unique_ptr<GpuMesh> surroundings, ball, tee, flag, impactor, poles, stands;
  std::vector<std::unique_ptr<GpuMesh>> dressing;  // a ballpark's diamond, lowest layer first
  double impactor_size = 0.0;  // m, the impactor mesh's longest box side
  bool impactor_is_bat = false;
  std::optional<Vec3> flag_position;
  std::vector<std::pair<double, Vec3>> fence_marks;  // (distance m, label anchor)
  Vec3 world_min = Vec3::Zero(), world_max = Vec3::Zero();  // the world mesh's box, m
  double plane_y = 0;  // the surrounding grass plane, m
};

const ShotSceneInput& ShotScene::input() const { return impl_->input; }
void ShotScene::set_wind(const Vec3& wind) { impl_->input.wind = wind; }
void ShotScene::set_people(PeopleFn people) { impl_->input.people = std::move(people); }
void ShotScene::set_target_line(const Vec3& line) { impl_->input.target_line = line; }

ShotScene::ShotScene(const ShotSceneInput& input, const SceneStyle& style) : impl_(std::make_unique<Impl>()) {
  Impl& m = *impl_;
  m.input = input;
  m.style = style;
  if (input.assets == nullptr) throw InputError("render: no assets given");
  if (input.distance_unit != "yd" && input.distance_unit != "m" && input.distance_unit != "ft") {
    throw InputError("distance unit '" + input.distance_unit + "' is not one of: yd, m, ft");
  }
  if (!(input.ball_radius > 0.005 && input.ball_radius < 0.1)) {
    throw InputError("ball radius " + std::to_string(input.ball_radius) + " m is outside 0.005..0.1 m");
  }
  m.golf = input.distance_unit != "ft";
  const auto& root = input.assets->root();

  double ground_min_y = 0.0;
  if (input.world != nullptr) {
    const WorldDescription& d = input.world->description();
    const MeshData whole = world_mesh_data(d);
    // The ground's surfaces (turf, sand, water, dirt: a textured look) meet edge to edge and
    // tile to tile; coarsened apart, each would pull its copy of the shared corners toward its
    // own middle and open a crack there, up to a cell wide, that a far view or the map shows
    // as a grid of dark lines. Trees and walls stand on their own and keep their own means.
    const auto ground = [](const Vertex& v) { return v.pattern != surface_look::kPlain && v.pattern != surface_look::kCloth; };
    std::array<SharedCells, kFarLevels.size()> shared;
    for (std::size_t l = 0; l < kFarLevels.size(); ++l) shared[l] = shared_cells(whole, kFarLevels[l].cell, ground);
    for (MeshData& tile : split_into_tiles(whole, kWorldTile)) {
      Eigen::AlignedBox3f box;
      for (const Vertex& v : tile.vertices) box.extend(v.position);
      Impl::Tile w;
      w.mesh = std::make_unique<GpuMesh>(tile);
      w.box = box;
      for (std::size_t l = 0; l < kFarLevels.size(); ++l)
        w.far[l] = std::make_unique<GpuMesh>(cluster_vertices(tile, kFarLevels[l].cell, &shared[l]));
      m.world.push_back(std::move(w));
    }
    ground_min_y = 1e300;
    m.world_min = Vec3::Constant(1e300);
    m.world_max = Vec3::Constant(-1e300);
    for (const WorldMesh& wm : d.meshes)
      for (const Vec3& p : wm.vertices) {
        m.world_min = m.world_min.cwiseMin(p);
        m.world_max = m.world_max.cwiseMax(p);
      }
    ground_min_y = m.world_min.y();
    m.flag_position = input.flag ? input.flag : input.world->pin;
    // Fence distances where the foul lines, the gaps and centre field meet the fence line.
    if (!input.world->fence_line.empty()) {
      for (double deg : {-45.0, -22.5, 0.0, 22.5, 45.0}) {
        const Vec3 dir(std::cos(deg_to_rad(deg)), 0.0, std::sin(deg_to_rad(deg)));
        const Vec3 origin(d.origin.x(), ground_height(d.origin.x(), d.origin.z()).value_or(d.origin.y()) + 0.5,
                          d.origin.z());
        if (const auto hit = ray_polyline(origin, dir, input.world->fence_line)) {
          m.fence_marks.emplace_back(*hit, origin + *hit * dir);
        }
      }
      if (input.distance_unit == "ft") {
        const Vec3 home(d.origin.x(), ground_height(d.origin.x(), d.origin.z()).value_or(d.origin.y()), d.origin.z());
        const BallparkDressing dress = ballpark_dressing(home, input.world->fence_line, input.world->fence_height);
        for (const MeshData& layer : dress.layers) m.dressing.push_back(std::make_unique<GpuMesh>(layer));
        m.poles = std::make_unique<GpuMesh>(dress.poles);
        if (!dress.stands.indices.empty()) m.stands = std::make_unique<GpuMesh>(dress.stands);
      }
    }
  } else {
    m.flag_position = input.flag;
  }
  // Beyond the world mesh: a grass plane just below its lowest point, out to the horizon.
  m.plane_y = !m.world.empty() ? ground_min_y - 0.3 : 0.0;
  // Without a world the plane is the flat default ground of the flight model: a mown fairway.
  m.surroundings = std::make_unique<GpuMesh>(grass_plane(m.plane_y, 4000.0, !m.world.empty() ? "out_of_bounds" : "fairway"));
  m.ball = std::make_unique<GpuMesh>(import_mesh(mesh_path(root, "golf_ball")));
  if (input.tee) m.tee = std::make_unique<GpuMesh>(import_mesh(mesh_path(root, "tee")));
  if (m.flag_position) m.flag = std::make_unique<GpuMesh>(import_mesh(mesh_path(root, "flag")));
  if (!input.impactor_mesh.empty()) {
    const MeshData club = import_mesh(mesh_path(root, input.impactor_mesh));
    Eigen::Vector3f lo = Eigen::Vector3f::Constant(1e30f), hi = Eigen::Vector3f::Constant(-1e30f);
    for (const Vertex& v : club.vertices) {
      lo = lo.cwiseMin(v.position);
      hi = hi.cwiseMax(v.position);
    }
    m.impactor_size = club.vertices.empty() ? 0.0 : static_cast<double>((hi - lo).maxCoeff());
    m.impactor_is_bat = input.impactor_mesh == "bat";
    m.impactor = std::make_unique<GpuMesh>(club);
  }
  impactor_ = input.impactor;
}

ShotScene::~ShotScene() = default;

void ShotScene::set_shot(const ShotTrajectory& trajectory, const std::optional<ImpactorPlacement>& impactor) {
  trajectory_ = trajectory;
  impactor_ = impactor;
  side_down_.reset();
}

std::optional<double> ShotScene::ground_height(double x, double z) const {
  const WorldAsset* w = impl_->input.world;
  if (w == nullptr) return std::nullopt;
  const WorldDescription& d = w->description();
  SurfaceContact hit;
  // Straight down from the top of the world: the highest ground under (x, z).
  if (!ground_under(*w->world, x, z, d.bounds_max.y(), d.bounds_max.y() - d.bounds_min.y(), &hit))
    return std::nullopt;
  return hit.point.y();
}

Camera ShotScene::camera(CameraKind kind, double t, int width, int height, const FrameWindow& window) const {
  ShotFraming f = shot_framing(trajectory_, t);
  f.target_line = impl_->input.target_line;
  if (impactor_) f.points.push_back(impactor_->position);
  // From above, a ballpark shows the whole park, fence to fence (a spray chart's view).
  if (kind == CameraKind::Top && impl_->input.world != nullptr)
    for (const Vec3& p : impl_->input.world->fence_line) f.points.push_back(p);
  if (kind == CameraKind::Side) f.side_down = side_down(f, width, height);
  // Follow sits close to the ball and may dip to grass height; 0.3 m keeps it off the blades.
  if (kind != CameraKind::Follow) return keep_above_ground(frame_shot(kind, f, width, height, window), 1.0);
  return keep_clear_of_trees(keep_above_ground(frame_shot(kind, f, width, height, window), 0.3), f.ball);
}

double ShotScene::side_down(const ShotFraming& framing, int width, int height) const {
  const double usual = framing.side_down;
  const WorldAsset* w = impl_->input.world;
  if (w == nullptr || framing.points.size() < 2) return usual;
  if (side_down_ && std::get<0>(*side_down_) == width && std::get<1>(*side_down_) == height) return std::get<2>(*side_down_);
  const Terrain& terrain = *w->world;
  // The flight at ~20 points along it, each seen past a tree or not.
  constexpr int kLooks = 20;
  constexpr double kSight = 0.05;  // m: a sight line, not a ball
  const auto hidden = [&](const Vec3& eye) {
    int n = 0;
    for (int i = 0; i < kLooks; ++i) {
      const Vec3& p = framing.points[(framing.points.size() - 1) * static_cast<std::size_t>(i) / (kLooks - 1)];
      SurfaceContact hit;
      if (terrain.may_touch(eye, p, kSight) && terrain.sweep(eye, p, kSight, &hit, nullptr) &&
          terrain.material(hit.material).kind == SurfaceKind::Tree)
        ++n;
    }
    return n;
  };
  double best = usual;
  int fewest = kLooks + 1;
  for (const double deg : {10.0, 20.0, 30.0, 45.0, 60.0}) {
    ShotFraming f = framing;
    f.side_down = deg_to_rad(deg);
    const int n = hidden(keep_above_ground(frame_shot(CameraKind::Side, f, width, height), 1.0).eye);
    if (n < fewest) fewest = n, best = f.side_down;
    if (n * 10 <= kLooks) break;  // a tenth or less of it behind the trees
  }
  side_down_ = std::make_tuple(width, height, best);
  return best;
}

Camera ShotScene::keep_clear_of_trees(Camera c, const Vec3& subject) const {
  const WorldAsset* w = impl_->input.world;
  if (w == nullptr) return c;
  // The eye's room among the leaves: wider than the follow camera's 0.1 m near plane, so the
  // crown's faces never cut through the view.
  constexpr double kRoom = 0.4;  // m
  const Terrain& terrain = *w->world;
  // The first tree on the sight line from the subject to `eye`, as the fraction of the way.
  const auto tree_between = [&](const Vec3& eye) -> std::optional<double> {
    SurfaceContact hit;
    if (!terrain.may_touch(subject, eye, kRoom) || !terrain.sweep(subject, eye, kRoom, &hit, nullptr)) return std::nullopt;
    if (terrain.material(hit.material).kind != SurfaceKind::Tree) return std::nullopt;
    return hit.fraction;
  };
  const auto blocked = tree_between(c.eye);
  if (!blocked) return c;
  // Raised in 5 deg steps (small enough that the view turns, rather than jumps, as the ball
  // runs past a tree): the eye keeps its distance and its bearing from the ball.
  const Vec3 from_subject = c.eye - subject;
  const double reach = from_subject.norm();
  const double flat = std::hypot(from_subject.x(), from_subject.z());
  if (reach > 1e-6 && flat > 1e-6) {
    const Vec3 bearing(from_subject.x() / flat, 0.0, from_subject.z() / flat);
    const double from = std::atan2(from_subject.y(), flat);
    constexpr double kStep = deg_to_rad(5.0), kSteepest = deg_to_rad(80.0);
    for (double e = std::max(from, 0.0) + kStep; e <= kSteepest + 1e-9; e += kStep) {
      const Vec3 eye = subject + reach * (std::cos(e) * bearing + std::sin(e) * Vec3::UnitY());
      if (tree_between(eye)) continue;
      c.eye = eye;  // looking at the same place, from higher up
      return c;
    }
  }
  c.eye = subject + *blocked * (c.eye - subject);
  return c;
}

double ShotScene::pre_roll() const { return swing_pre_roll(impactor_, impl_->input.impactor_mesh); }

Camera ShotScene::keep_above_ground(Camera c, double clearance) const {
  const double ground = ground_height(c.eye.x(), c.eye.z()).value_or(impl_->plane_y);
  if (c.eye.y() < ground + clearance) c.eye.y() = ground + clearance;
  return c;
}

Scene ShotScene::build(const Camera& camera, double t, int width, int height) const {
  const Impl& m = *impl_;
  Scene scene;
  auto ground_at = [&](double x, double z) { return ground_height(x, z).value_or(m.plane_y); };
  // Decoration sizes are styled for 720 lines and scale with the image, but not below 3/4: the
  // stroke font's digits run together under ~12 px ("400" read "4ΛΛ" at 480 lines).
  const double style_scale = std::max(0.75, height / 720.0);
  auto px = [&](const Vec3& p, double pixels) { return style_scale * pixels * camera.metres_per_pixel(p, height); };

  // The sun's shadow map covers what the camera frames: the whole shot (and the park) from
  // afar, the few metres in view when the camera is close to the ball.
  {
    const Vec3 focus = camera.target;
    const double reach = (camera.target - camera.eye).norm();
    Bounds b = shot_bounds(trajectory_);
    b.add(camera.target);
    const double span = 0.5 * (b.max - b.min).norm() + 10.0;
    // Close up, a square twice the view distance: ~1 cm texels on the 2048 map for the
    // follow camera, so a shaft's shadow is a line, not dashes.
    const bool close = reach < 40.0;
    scene.shadow_centre = (close ? focus : b.centre()).cast<float>();
    scene.shadow_radius = static_cast<float>(close ? std::max(8.0, reach) : std::min(span, 300.0));
  }
  const Eigen::Vector3f eye = camera.eye.cast<float>();
  for (const Impl::Tile& tile : m.world) {
    // The level of detail by the tile's distance: its nearest point to the eye.
    const float d = (eye - eye.cwiseMax(tile.box.min()).cwiseMin(tile.box.max())).norm();
    const GpuMesh* mesh = tile.mesh.get();
    for (std::size_t l = 0; l < kFarLevels.size(); ++l)
      if (d > kFarLevels[l].from) mesh = tile.far[l].get();
    MeshInstance inst{mesh, Eigen::Matrix4f::Identity(), true, 0, tile.box};
    scene.meshes.push_back(inst);
  }
  for (std::size_t i = 0; i < m.dressing.size(); ++i)
    scene.meshes.push_back({m.dressing[i].get(), Eigen::Matrix4f::Identity(), false, static_cast<int>(i) + 1});
  if (m.poles) scene.meshes.push_back({m.poles.get(), Eigen::Matrix4f::Identity(), false});
  if (m.stands) scene.meshes.push_back({m.stands.get(), Eigen::Matrix4f::Identity(), false});
  scene.meshes.push_back({m.surroundings.get(), Eigen::Matrix4f::Identity(), true});

  const auto& samples = trajectory_.samples;
  const bool have_shot = !samples.empty();
  const TrajectorySample at = sample_at(trajectory_, t);
  const Vec3 launch = have_shot ? samples.front().position : Vec3(0, m.input.ball_radius, 0);

  if (m.tee) {
    // The tee's cup holds the ball's bottom; its peg reaches down into the turf.
    scene.meshes.push_back({m.tee.get(), translate_scale(launch - Vec3(0, m.input.ball_radius, 0), 1.0), false});
  }
  if (m.flag) {
    // The cloth (+x in its mesh) streams downwind and flutters, the more the stronger the
    // wind (a flag stands out from ~3 m/s; ESTIMATE of the flutter: ±0.25 rad at 2 Hz in a
    // breeze, less in a gale that holds it straight); in a calm it hangs as modelled.
    Eigen::Matrix4f model = translate_scale(*m.flag_position, 1.0);
    const Vec3& wind = m.input.wind;
    const double speed = std::hypot(wind.x(), wind.z());
    if (speed > 0.3) {
      const double flutter = 0.25 / (1.0 + 0.1 * speed) * std::sin(2.0 * kPi * 2.0 * std::max(t, 0.0));
      const double yaw = std::atan2(wind.z(), wind.x()) + flutter;  // rad right of +x
      model.block<3, 3>(0, 0) = Eigen::AngleAxisf(static_cast<float>(-yaw), Eigen::Vector3f::UnitY()).toRotationMatrix();
    }
    scene.meshes.push_back({m.flag.get(), model, false});
  }
  // The tee box's markers: two blocks of the tee set's colour either side of the tee spot.
  for (const auto& [at, colour] : m.input.tee_markers)
    append_limb(scene.figures, at, at + Vec3(0.0, 0.18, 0.0), 0.14, colour);
  if (m.input.people) m.input.people(PeopleFrame{t, &camera, height}, scene.figures);
  // The club or bat at impact, at least impactor_min_px on screen: scaled about the ball's
  // centre at launch (the ball is drawn as big at that moment), so face and ball still touch.
  double strike_scale = 1.0;
  // The delivery is known (a solved impact, not launch numbers drawn in a nominal pose):
  // exactly when there is a downswing to show.
  const bool delivered = pre_roll() > 0.0;
  // A golfer who stands kGolferReadsPx tall or more is drawn, with his club at true size: the
  // view is close enough to watch the swing, not only the strike.
  const bool golfer_reads = delivered && !m.impactor_is_bat && kGolferHeight > px(launch, kGolferReadsPx);
  if (m.impactor && impactor_) {
    if (m.impactor_size > 0.0 && !golfer_reads)
      strike_scale = std::max({1.0, px(launch, m.style.impactor_min_px) / m.impactor_size,
                               px(launch, m.style.ball_min_radius_px) / m.input.ball_radius});
    // Before launch (the replay's pre-roll, t < 0) it is on its downswing, after it on its
    // follow-through (swing_pose.hpp). A club drawn larger for a far camera stays at impact:
    // there it shows the strike, and a magnified club sweeping round would hide the view.
    ImpactorPlacement pose = *impactor_;
    const bool true_size = strike_scale <= 1.0 + 1e-9;
    if (delivered && (t < 0.0 || true_size)) {
      const Vec3 v = impactor_->velocity.normalized();
      const Vec3 contact = launch - m.input.ball_radius * v;
      const Vec3 shaft = m.impactor_is_bat ? Vec3(-(impactor_->orientation * Vec3::UnitX()))
                                           : Vec3(impactor_->orientation * head_frame_shaft_axis());
      pose = swing_pose(*impactor_, contact, shaft, t, swing_shape(m.input.impactor_mesh));
    }
    Eigen::Matrix4f model = Eigen::Matrix4f::Identity();
    model.block<3, 3>(0, 0) = static_cast<float>(strike_scale) * pose.orientation.normalized().toRotationMatrix().cast<float>();
    model.block<3, 1>(0, 3) = (launch + strike_scale * (pose.position - launch)).cast<float>();
    scene.meshes.push_back({m.impactor.get(), model, false});
    // The golfer holding it, where his hands must be: the grip rides with the club through
    // its downswing and follow-through. Only at true size: a club drawn larger for a far
    // camera has no hands on it.
    if (!m.impactor_is_bat && delivered && true_size) {
      const Vec3 v = impactor_->velocity.normalized();
      Vec3 target = trajectory_.summary.rest_position - launch;
      target.y() = 0.0;
      if (target.norm() < 0.5) target = Vec3(v.x(), 0.0, v.z());
      add_golfer(scene, m.input.impactor_mesh, pose, *impactor_, target, ground_at(launch.x(), launch.z()));
    }
  }
  // A ball waiting to be hit: the club behind it at address, in the golfer's hands.
  if (m.impactor && !impactor_ && address_ && !m.impactor_is_bat) {
    const ImpactorPlacement& club = *address_;
    const Vec3 target = aim_ ? *aim_ : Vec3(club.orientation * Vec3::UnitX());
    ImpactorPlacement held = club;
    if (backswing_ > 0.0) {
      // Wound back along the arc the downswing comes down: the strike's pose run backwards
      // from the ball to the top. The speed only sets how far round the top lies (a full
      // swing's ~4 rad at a tour driver's 50 m/s; a putt's backstroke at 2 m/s).
      Vec3 along(target.x(), 0.0, target.z());
      along = along.norm() > 1e-9 ? along.normalized() : Vec3::UnitX();
      const bool putter = m.input.impactor_mesh == "putter_head";
      ImpactorPlacement through = club;
      through.velocity = (putter ? 2.0 : 50.0) * along;
      const SwingShape& shape = swing_shape(m.input.impactor_mesh);
      // The downswing speeds up evenly from the top, so the arc from the ball is a share
      // 1 − (1 − τ)² of the whole at a share τ of its time: wound back by the share
      // `backswing_` of the arc (the meter's power), τ = 1 − √(1 − backswing_).
      const double tau = 1.0 - std::sqrt(1.0 - backswing_);
      held = swing_pose(through, launch - m.input.ball_radius * along, club.orientation * head_frame_shaft_axis(),
                        -tau * shape.downswing, shape);
    }
    Eigen::Matrix4f model = Eigen::Matrix4f::Identity();
    model.block<3, 3>(0, 0) = held.orientation.normalized().toRotationMatrix().cast<float>();
    model.block<3, 1>(0, 3) = held.position.cast<float>();
    scene.meshes.push_back({m.impactor.get(), model, false});
    add_golfer(scene, m.input.impactor_mesh, held, club, target, ground_at(launch.x(), launch.z()));
  }
  // The ball: true size close up, never smaller than ball_min_radius_px on screen.
  const Vec3 ball = have_shot ? at.position : launch;
  const double radius = std::max(m.input.ball_radius, px(ball, m.style.ball_min_radius_px));
  scene.meshes.push_back({m.ball.get(), translate_scale(ball, radius / 0.021335), false});
  // Its shadow straight below (the sun near noon), as big as the ball is drawn: the eye
  // reads the ball's height from the gap between them, as on television.
  {
    const Vec3 g(ball.x(), ground_at(ball.x(), ball.z()) + 0.02, ball.z());
    append_ring(scene.ground_overlay, g, 0.0, 1.1 * radius, kBallShadowColor, 20);
  }
  // The delivery at the ball, as a coach draws it: the club path (with its attack angle)
  // through the back of the ball, and for a club the face's normal. Sized with the strike.
  if (delivered) {
    const Vec3 v = impactor_->velocity.normalized();
    const Vec3 back = launch - strike_scale * m.input.ball_radius * v;
    const double len = 0.5 * strike_scale, w = px(back, 3.0);
    append_band(scene.top_overlay, back - len * v, back + 0.4 * len * v, w, back - camera.eye, kPathColor);
    if (!m.impactor_is_bat) {
      // HEAD FRAME: the face normal is the mesh's +x (shot_view.cpp nominal_impactor).
      const Vec3 face = impactor_->orientation.normalized() * Vec3::UnitX();
      append_band(scene.top_overlay, back, back + 0.7 * len * face, w, back - camera.eye, kFaceColor);
    }
  }

  // A line on the ground `pixels` wide, widened across the line of sight (so it reads from
  // a grazing behind view as well as from above) and lifted by half its width.
  auto ground_line = [&](const Vec3& a, const Vec3& b, double pixels, const Eigen::Vector3f& color) {
    const Vec3 lift(0, 0.5 * px(a, pixels) + 0.02, 0);
    append_band(scene.ground_overlay, a + lift, b + lift, px(a, pixels), a - camera.eye, color);
  };
  // Trail up to t, and its ground track (the flight's shadow at noon) so the eye can tell
  // height from distance in the behind view.
  if (have_shot) {
    TrailStyle trail{m.style.trail_width_px * std::max(1.0, style_scale), height};
    trail.glow_px = m.style.trail_glow_px * std::max(1.0, style_scale);
    append_trail(scene.top_overlay, trajectory_, t, camera, trail);
    std::size_t last = 0;
    sample_at(trajectory_, t, &last);
    const std::size_t stride = std::max<std::size_t>(1, samples.size() / 300);
    Vec3 prev = Vec3::Constant(std::nan(""));
    for (std::size_t i = 0; i <= last; i += stride) {
      if (samples[i].phase != Phase::Flight) break;
      const Vec3& q = samples[i].position;
      const Vec3 g(q.x(), ground_at(q.x(), q.z()) + 0.04, q.z());
      if (!std::isnan(prev.x())) ground_line(prev, g, 2.0, kTrackColor);
      prev = g;
    }
  }

  // Arrows on the ground, each with a head of two barbs back from its tip.
  for (const GroundArrow& a : arrows_) {
    Vec3 d = a.to - a.from;
    d.y() = 0.0;
    const double len = d.norm();
    if (len < 1e-6) continue;
    d /= len;
    const Vec3 side(-d.z(), 0.0, d.x());
    const double head = std::min(0.35 * len, 0.3);
    ground_line(a.from, a.to, 2.5, a.color);
    for (const double s : {-1.0, 1.0}) ground_line(a.to, a.to - head * (0.87 * d + s * 0.5 * side), 2.5, a.color);
  }

  // Distance markers: stripes across the golf hole every 50 yd; fence distances in a park.
  const Vec3 cam_right = camera.right(), cam_up = camera.true_up();
  // Labels never overlap on screen: each claims its rectangle, and a label that would
  // cover an earlier one is left out (shot labels go first, so they win).
  std::vector<Eigen::Vector4d> taken;  // x0, y0, x1, y1 in pixels
  // A box kept free for the game's own flag (below), not a label of the image: the game's
  // flagstick keeps clear of label_boxes and would leave a gap over itself.
  std::optional<std::size_t> flag_box;
  // False when the label was left out.
  auto label = [&](const std::string& text, const Vec3& anchor, const Eigen::Vector3f& color) {
    const double h = px(anchor, m.style.label_height_px);
    Vec3 origin = anchor - 0.5 * text_width(text, h) * cam_right;
    auto at_px = camera.project(origin, width, height);
    if (!at_px) return false;
    const double h_px = style_scale * m.style.label_height_px;
    const double w_px = text_width(text, h_px), pad = 3.0;
    // Slide a label that would stick out of the image back in horizontally.
    const double shift = std::max(0.0, pad - at_px->x()) - std::max(0.0, at_px->x() + w_px + pad - width);
    origin += shift * px(anchor, 1.0) / style_scale * cam_right;
    at_px->x() += shift;
    // Kept a word's space apart from the labels already placed: "150" and "200" of two
    // far stripes squeezed edge to edge read as one number.
    const double gap = 0.5 * h_px;
    const Eigen::Vector4d r(at_px->x() - gap, at_px->y() - h_px - pad, at_px->x() + w_px + gap,
                            at_px->y() + text_descent(h_px) + pad);
    for (const auto& o : taken) {
      if (r[0] < o[2] && o[0] < r[2] && r[1] < o[3] && o[1] < r[3]) return false;
    }
    taken.push_back(r);
    // A dark drop shadow keeps light labels readable over sand, sky and light greens.
    const Vec3 shadow = origin + (cam_right - cam_up) * px(anchor, 1.5);
    append_text(scene.top_overlay, text, shadow, cam_right, cam_up, h, kShadowColor);
    append_text(scene.top_overlay, text, origin, cam_right, cam_up, h, color);
    return true;
  };
  // The trail colours' key, bottom-left, claimed first so no label covers it; none for a
  // ball lying still (a golfer at address, a hole's flyover): no trail for it to explain.
  const bool trail = samples.size() >= 2 && (samples.back().position - samples.front().position).norm() > 1e-3;
  if (trail && m.style.legend) {
    std::vector<LegendEntry> keys = {
        {phase_color(Phase::Flight), "flight"}, {phase_color(Phase::Bounce), "bounce"}, {phase_color(Phase::Roll), "roll"}};
    if (delivered) keys.push_back({kPathColor, "path"});
    if (delivered && !m.impactor_is_bat) keys.push_back({kFaceColor, "face"});
    taken.push_back(append_legend(scene.top_overlay, keys, camera, width, height, style_scale));
  }
  // A park's fence distances are its painted signs: placed before the shot's labels, so a
  // ball caught at the wall is labelled beside the sign, never over it in its place.
  if (!m.golf)
    for (const auto& [dist, at_wall] : m.fence_marks) label(format_distance(dist, "ft"), at_wall + Vec3(0, 4.0, 0), kFenceLabelColor);
  // A shot's label, where it claims its room: at `anchor`, else stepped a line at a time up
  // and down the screen in turn (a few tries) until clear of the labels already placed, so
  // it stays beside its mark rather than climbing away over the stands.
  const auto shot_label = [&](const std::string& text, const Vec3& anchor, const Vec3& ground, const Eigen::Vector3f& color) {
    for (const int k : {0, 1, -1, 2, -2, 3})
      if (label(text, anchor + cam_up * px(ground, 1.8 * m.style.label_height_px * k), color)) return;
  };
  // Landing ring with the carry, rest pin with the total (golf yards, baseball feet).
  std::vector<Vec3> shot_labels_at;  // where on the ground the shot's own distances are written
  if (have_shot) {
    const auto& s = trajectory_.summary;
    const double end_t = samples.back().t;
    // A putt never leaves the ground: no carry.
    const bool rolled_only = s.rolled_only();
    // One unit on one trail: a chip that carries 16 m and runs out to 26 m reads in yards both
    // times, not "53 ft" beside "28 yd".
    const double scale = std::max(s.carry_m, s.total_m);
    const auto shown = [&](double metres) {
      return m.golf ? format_golf_distance(metres, m.input.distance_unit, scale) : format_distance(metres, m.input.distance_unit);
    };
    std::string carry_text;  // as written at the landing ring, if it is
    if (s.hang_time_s > 0 && !rolled_only && t >= s.hang_time_s - 1e-9) {
      const Vec3 lp = s.landing_position;
      const Vec3 g(lp.x(), ground_at(lp.x(), lp.z()) + 0.05, lp.z());
      const double r = px(g, m.style.marker_radius_px);
      append_ring(scene.ground_overlay, g, 0.65 * r, r, kLandingColor);
      if (carry_label_) {
        carry_text = carry_words_.empty() ? shown(s.carry_m) : carry_words_ + " " + shown(s.carry_m);
        shot_label(carry_text, g + cam_up * px(g, 14.0) - cam_right * px(g, 40.0), g, kLandingColor);
        shot_labels_at.push_back(g);
      }
    }
    if (t >= end_t - 1e-9 && (s.rest_position - s.landing_position).norm() > 0.5) {
      const Vec3 rp = s.rest_position;
      const Vec3 g(rp.x(), ground_at(rp.x(), rp.z()), rp.z());
      const double h = px(g, 30.0);
      append_pin(scene.top_overlay, g, h, px(g, 2.5), cam_right, kRestColor);
      const std::string text = rest_label_.value_or(rest_words_.empty() ? shown(s.total_m) : rest_words_ + " " + shown(s.total_m));
      // A ball that stopped within the last figure of its carry would read the same number
      // twice, a few pixels apart: the ring's label says it.
      if (!text.empty() && text != carry_text) {
        shot_label(text, g + Vec3(0, h, 0) + cam_up * px(g, 6.0), g, kRestColor);
        shot_labels_at.push_back(g);
      }
    }
  }

  if (m.golf) {
    // One reference for every distance: the ball's start. Lines across the shot's aim every
    // 50 yd (50 m in metres) from there, out past the shot and the flag (or to the end of a
    // world without one).
    Vec3 aim = aim_.value_or(Vec3::UnitX());
    if (!aim_ && have_shot) {
      Vec3 d = samples.back().position - launch;
      d.y() = 0;
      if (d.norm() > 1.0) aim = d.normalized();
    }
    aim.y() = 0;
    aim = aim.norm() > 1e-9 ? aim.normalized() : Vec3::UnitX();
    const Vec3 across(-aim.z(), 0.0, aim.x());  // right of the aim line
    const double stripe = 50.0 * unit_length(m.input.distance_unit);  // m between the lines
    const bool on_hole = !m.world.empty() && m.flag_position;
    // On a hole: to the stripe nearest past the flag (a course's world runs on over the other
    // holes), so a putt or a chip, all of it well inside the first stripe, has none.
    double reach = on_hole ? 0.0 : 60.0;
    for (const auto& q : samples) reach = std::max(reach, (q.position - launch).dot(aim) + (on_hole ? 0.0 : 20.0));
    if (on_hole) {
      reach = std::max(reach, (*m.flag_position - launch).dot(aim) + 0.5 * stripe);
    } else if (!m.world.empty()) {
      for (double x : {m.world_min.x(), m.world_max.x()})
        for (double z : {m.world_min.z(), m.world_max.z()}) reach = std::max(reach, (Vec3(x, 0, z) - launch).dot(aim));
    }
    const double half = 22.0;
    // Each stripe's number sits just left of the aim line, where the player looks, not at
    // the stripe's end (under the panels, or off the image). Toward the horizon the stripes
    // close up on screen: a number is left out unless it stands a line's height clear of any
    // number written above or below it, so the far ones never run together.
    const double h_px = style_scale * m.style.label_height_px, line_px = 1.6 * h_px;
    std::vector<Eigen::Vector3d> numbers;  // px: left, right, baseline of each number written
    // Nor over the flag: the game draws a far flag at least 40 px tall (game/ui/golf_marks),
    // and a number behind its cloth reads as another ("1$0"). The scene's own cloth flies
    // with the wind, either side of the pole (and edge-on down a tail- or headwind, where a
    // number beside the pole hides all of it): the pole and a cloth's length both sides.
    // Right of the cloth the game writes how far the pin is ("505 yd", ImGui's 13 px font:
    // ~7 px a glyph), and the number is kept off that too.
    constexpr double kPinLabelPx = 56.0;
    double flag_reach_px = 0.0;  // from the pole to the box's edge
    if (on_hole) {
      const auto base = camera.project(*m.flag_position, width, height);
      const auto top = camera.project(*m.flag_position + Vec3(0.0, kFlagstickHeight, 0.0), width, height);
      if (base) {
        const double tall = std::max(40.0, top ? base->y() - top->y() : 0.0);
        flag_reach_px = 0.3 * tall + 4.0;
        flag_box = taken.size();
        taken.push_back(
            Eigen::Vector4d(base->x() - flag_reach_px, base->y() - tall - 4.0, base->x() + flag_reach_px + kPinLabelPx, base->y()));
      }
    }
    std::vector<std::pair<int, Vec3>> written;  // each stripe's number and where it sits
    for (int k = 1; k * stripe <= reach && k <= 20; ++k) {
      const Vec3 mid = launch + k * stripe * aim;
      if (!m.world.empty() && !ground_height(mid.x(), mid.z())) continue;  // off the world
      constexpr int n = 22;
      auto at = [&](double off) {
        const Vec3 q = mid + off * across;
        return Vec3(q.x(), ground_at(q.x(), q.z()), q.z());
      };
      for (int i = 0; i < n; ++i) ground_line(at(-half + 2 * half * i / n), at(-half + 2 * half * (i + 1) / n), 2.0, kWhite);
      written.emplace_back(k, at(0.0));
    }
    if (focus_)
      std::stable_sort(written.begin(), written.end(), [&](const auto& a, const auto& b) {
        return std::abs(a.first * stripe - *focus_) < std::abs(b.first * stripe - *focus_);
      });
    // A tree between the eye and a stripe's number hides the number, as it hides the stripe
    // (the numbers are drawn over the scene, the stripes in it): "250" written on a crown
    // reads as the distance to the tree. Tested half a metre over the ground the number marks.
    const auto behind_tree = [&](const Vec3& p) {
      if (m.input.world == nullptr || m.input.world->trees.empty()) return false;
      // Only a crown whose footprint the sight line crosses (seen from above) can hide it:
      // the world's sweep runs only then.
      const Eigen::Vector2d a(camera.eye.x(), camera.eye.z()), b(p.x(), p.z());
      const Eigen::Vector2d ab = b - a;
      const double ab2 = std::max(ab.squaredNorm(), 1e-12);
      const bool crosses = std::any_of(m.input.world->trees.begin(), m.input.world->trees.end(), [&](const TreeCrown& c) {
        const Eigen::Vector2d q(c.centre.x(), c.centre.z());
        const double u = std::clamp((q - a).dot(ab) / ab2, 0.0, 1.0);
        return (a + u * ab - q).norm() <= c.radius;
      });
      if (!crosses) return false;
      const Terrain& terrain = *m.input.world->world;
      constexpr double kSight = 0.05;  // m: a sight line, not a ball
      SurfaceContact hit;
      if (!terrain.may_touch(camera.eye, p, kSight) || !terrain.sweep(camera.eye, p, kSight, &hit, nullptr)) return false;
      return terrain.material(hit.material).kind == SurfaceKind::Tree;
    };
    // No gap between two numbers written: once a stripe's number is crowded out, none is
    // written on its far side from one already there, so a "150" never stands just above a
    // "50" as if they were neighbours.
    std::vector<int> placed_k, crowded_out;
    const auto past_a_gap = [&](int k) {
      for (const int p : placed_k)
        for (const int j : crowded_out)
          if ((j - k) * (j - p) < 0) return true;  // j strictly between k and p
      return false;
    };
    // The ball's own distance written within a few yards of a stripe says the distance there:
    // "203 yd" over its pin stacked on a "200" reads as two answers. Within 15 % of the spacing
    // and inside the stripe's width, the stripe keeps its line and gives up its number (the gap
    // rule above does not count it: the ball's label stands in for it).
    const auto beside_shot_label = [&](int k) {
      return std::any_of(shot_labels_at.begin(), shot_labels_at.end(), [&](const Vec3& g) {
        const Vec3 d = g - launch;
        return std::abs(d.dot(aim) - k * stripe) < 0.15 * stripe && std::abs(d.dot(across)) < half;
      });
    };
    // Nor a stripe at the flag: its "50" just under a pin 53 yd away reads as the pin's
    // distance, which the game writes beside the cloth. The same 15 % of the spacing.
    const auto at_the_flag = [&](int k) {
      if (!on_hole) return false;
      const Vec3 d = *m.flag_position - launch;
      return std::abs(d.dot(aim) - k * stripe) < 0.15 * stripe && std::abs(d.dot(across)) < half;
    };
    if (!stripe_numbers_) written.clear();  // the stripes drawn above, without their numbers
    for (const auto& [k, on_line] : written) {
      const std::string text = std::to_string(k * 50);
      if (past_a_gap(k) || beside_shot_label(k) || at_the_flag(k)) continue;
      const auto seen = camera.project(on_line, width, height);
      // A stripe whose middle is out of the picture has no number: slid in to the image's
      // edge, the side view's far stripes would stand there in a column ("450 50 300 150").
      if (!seen || seen->x() < 0.0 || seen->x() > width || seen->y() < 0.0 || seen->y() > height) continue;
      const double w_px = text_width(text, h_px);
      const Eigen::Vector3d box(seen->x() - w_px - 8.0 * style_scale, seen->x(), seen->y());
      const bool crowded = std::any_of(numbers.begin(), numbers.end(), [&](const Eigen::Vector3d& o) {
        return box[0] < o[1] + h_px && o[0] < box[1] + h_px && std::abs(box[2] - o[2]) < line_px;
      });
      if (crowded) {
        crowded_out.push_back(k);
        continue;
      }
      if (behind_tree(on_line + Vec3(0.0, 0.5, 0.0))) continue;
      // Just left of the aim line; where the flag stands there, left of the flag instead.
      const double beside = 8.0 * style_scale;  // px from the line to the number
      bool placed = false;
      for (const double clear_px : {beside, beside + flag_reach_px}) {
        if (clear_px > beside && flag_reach_px == 0.0) break;
        if (label(text, on_line + cam_up * px(on_line, 6.0) - cam_right * px(on_line, (0.5 * w_px + clear_px) / style_scale), kWhite)) {
          numbers.push_back(box - Eigen::Vector3d(clear_px - beside, clear_px - beside, 0.0));
          placed_k.push_back(k);
          placed = true;
          break;
        }
      }
      if (!placed) crowded_out.push_back(k);
    }
  }

  for (std::size_t i = 0; i < taken.size(); ++i)
    if (i != flag_box) scene.label_boxes.push_back(taken[i].cast<float>());
  return scene;
}

}  // namespace sweetspot
