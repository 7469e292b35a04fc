// The batting cage's people in the 3D scene (game/ui/cage_people.hpp): they keep the scene's
// clock (a clip of the play, drawn after play has moved on, shows the fielders running as
// they ran), they hold what they draw by value, and a far figure keeps a few pixels of width.
#include <catch2/catch.hpp>

#include <memory>

#include "game/ui/cage_people.hpp"
#include "support/test_assets.hpp"

using namespace sweetspot;

namespace {

// The mean of a mesh's vertices: where its figures stand, on the whole.
Vec3 centroid(const MeshData& m) {
  Vec3 c = Vec3::Zero();
  for (const Vertex& v : m.vertices) c += v.position.cast<double>();
  return m.vertices.empty() ? c : Vec3(c / static_cast<double>(m.vertices.size()));
}

Camera from_home() {
  Camera c;
  c.eye = Vec3(-3.0, 1.6, 0.0);
  c.target = Vec3(30.0, 1.0, 0.0);
  c.fov_y = deg_to_rad(40.0);
  return c;
}

}  // namespace

TEST_CASE("the cage's people run on the batted ball's clock and outlive the cage", "[ui][cage]") {
  auto cage = std::make_unique<BattingCage>(test::assets());
  // B: a pitch, and the pro swings at it (the cage's first pitch is squared up into the air).
  Intent b;
  b.kind = IntentKind::BotSwings;
  cage->update({b}, 0.0);
  double now = 0.0;
  while (cage->stage() != BattingCage::Stage::Batted && now < 10.0) {
    now += 0.01;
    cage->update({}, now);
  }
  REQUIRE(cage->stage() == BattingCage::Stage::Batted);
  REQUIRE(cage->last().result.contact);
  const PeopleFn people = cage_people(*cage, now);
  CHECK(cage_scene_time(*cage, now) == Approx(now - cage->batted_at()));
  cage.reset();  // a clip draws them after the cage has moved on (here: is gone)
  const Camera cam = from_home();
  MeshData at_contact, later, later_again;
  people(PeopleFrame{0.0, &cam, 720}, at_contact);
  people(PeopleFrame{3.0, &cam, 720}, later);
  people(PeopleFrame{3.0, &cam, 720}, later_again);
  // Eight fielders, a pitcher and a batter: 10 figures of 12 bones and a head (and a bat).
  CHECK(at_contact.vertices.size() >= 10u * 13u * 24u);
  CHECK(at_contact.vertices.size() == later.vertices.size());
  // Three seconds on the fielders have run toward the ball: the figures have moved.
  CHECK((centroid(later) - centroid(at_contact)).norm() > 0.5);
  // The same moment draws the same people.
  CHECK((centroid(later) - centroid(later_again)).norm() == 0.0);
}

TEST_CASE("a far figure keeps kFigureMinPx of width; a near one is drawn at its true size", "[ui][cage]") {
  const Camera cam = from_home();
  const auto torso_width = [&](double x) {
    Figure f;  // a torso and a head only: every other bone has no length
    for (Vec3& j : f.joint) j = Vec3(x, 1.0, 0.0);
    f.joint[kNeck] = Vec3(x, 1.6, 0.0);
    f.joint[kHead] = Vec3(x, 1.8, 0.0);
    MeshData m;
    append_figure(m, f, PeopleFrame{0.0, &cam, 720}, Eigen::Vector3f::Ones(), Eigen::Vector3f::Ones());
    double lo = 1e9, hi = -1e9;
    for (std::size_t i = 24; i < 48; ++i) {  // the torso's box, after the neck's (figure_bones)
      lo = std::min(lo, static_cast<double>(m.vertices[i].position.z()));
      hi = std::max(hi, static_cast<double>(m.vertices[i].position.z()));
    }
    return hi - lo;
  };
  // 20 m away a torso is ~0.3 m across, far more than 2.5 px (~0.02 m there).
  CHECK(torso_width(20.0) == Approx(0.3).epsilon(1e-6));
  // 500 m away 2.5 px is ~1.1 m: the torso is drawn that wide, so it still reads.
  const double mpp = cam.metres_per_pixel(Vec3(500.0, 1.3, 0.0), 720);
  CHECK(kFigureMinPx * mpp > 0.3);
  CHECK(torso_width(500.0) == Approx(kFigureMinPx * mpp).epsilon(1e-3));
}
