// The map's trees (game/content/tree_crowns): one crown per connected piece of a "tree"
// surface, its footprint's middle, top and spread; trunks and other surfaces left out.
#include <catch2/catch.hpp>

#include <cmath>

#include "game/content/tree_crowns.hpp"

using namespace sweetspot;

namespace {
// A six-sided crown as course import plants them: a ring of `r` m round (x, z) at height
// `base`, closed by a point `tall` m above it.
void add_crown(WorldMesh& m, double x, double z, double r, double base, double tall) {
  const auto first = static_cast<std::uint32_t>(m.vertices.size());
  for (int k = 0; k < 6; ++k) {
    const double a = 2.0 * 3.141592653589793 * k / 6.0;
    m.vertices.emplace_back(x + r * std::cos(a), base, z + r * std::sin(a));
  }
  m.vertices.emplace_back(x, base + tall, z);
  for (std::uint32_t k = 0; k < 6; ++k) {
    m.indices.insert(m.indices.end(), {first + k, first + 6, first + (k + 1) % 6});
    if (k >= 2) m.indices.insert(m.indices.end(), {first, first + k - 1, first + k});  // the crown's underside
  }
}
}  // namespace

TEST_CASE("tree crowns: one per crown, at its middle and top, as wide as it spreads; no trunk", "[content][trees]") {
  WorldDescription d;
  SurfaceMaterial rough;
  rough.name = "rough";
  rough.kind = SurfaceKind::Rough;
  SurfaceMaterial tree = rough;
  tree.name = "tree";
  tree.kind = SurfaceKind::Tree;
  SurfaceMaterial trunk = tree;
  trunk.name = "trunk";
  d.materials = {rough, tree, trunk};
  WorldMesh ground;
  ground.material = 0;
  ground.vertices = {Vec3(-100, 0, -100), Vec3(100, 0, -100), Vec3(100, 0, 100)};
  ground.indices = {0, 2, 1};
  WorldMesh crowns;
  crowns.material = 1;
  add_crown(crowns, 10.0, 5.0, 3.5, 4.0, 8.0);
  add_crown(crowns, -20.0, 30.0, 2.0, 3.0, 5.0);
  WorldMesh trunks;
  trunks.material = 2;
  add_crown(trunks, 10.0, 5.0, 0.3, 0.0, 4.0);
  d.meshes = {ground, crowns, trunks};
  const std::vector<TreeCrown> c = tree_crowns(d);
  REQUIRE(c.size() == 2);
  // The hexagon's box is symmetric across x, not across z (its corners at ±60°): the middle
  // is the box's, within the crown.
  CHECK(c[0].centre.x() == Approx(10.0));
  CHECK(c[0].centre.z() == Approx(5.0).margin(1e-9));
  CHECK(c[0].centre.y() == Approx(12.0));
  CHECK(c[0].radius == Approx(3.5).margin(1e-9));
  CHECK(c[1].centre.x() == Approx(-20.0));
  CHECK(c[1].centre.y() == Approx(8.0));
  CHECK(c[1].radius == Approx(2.0).margin(1e-9));
  d.meshes = {ground, trunks};
  CHECK(tree_crowns(d).empty());
}
