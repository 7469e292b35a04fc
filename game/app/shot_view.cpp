#include "game/app/shot_view.hpp"

namespace sweetspot {

std::string impactor_mesh_for(const Scenario& s) {
  if (s.launch) return "";
  if (s.sport == Sport::Baseball) return "bat";
  return s.club.loft < 25.0 * kPi / 180.0 ? "driver_head" : "iron_head";
}

std::optional<ImpactorPlacement> impactor_placement(const ShotResult& r) {
  if (!r.has_impactor) return std::nullopt;
  ImpactorPlacement p;
  p.position = r.impactor_at_impact.position;
  p.orientation = r.impactor_at_impact.orientation;
  return p;
}

ShotSceneInput scene_input_for(const Scenario& s, const ShotResult& r) {
  ShotSceneInput in;
  in.sport = to_string(s.sport);
  in.world = s.world;
  in.ball_radius = s.ball.radius;
  in.impactor = impactor_placement(r);
  in.impactor_mesh = in.impactor ? impactor_mesh_for(s) : "";
  return in;
}

RenderRequest render_request_for(const Scenario& s, const ShotResult& r) {
  const ShotSceneInput in = scene_input_for(s, r);
  RenderRequest req;
  req.sport = in.sport;
  req.world = in.world;
  req.ball_radius = in.ball_radius;
  req.impactor = in.impactor;
  req.impactor_mesh = in.impactor_mesh;
  return req;
}

}  // namespace sweetspot
