// Marks drawn on the course over the 3-D view: the cup and flag at any distance, the aim
// line, the map's rings and dispersion ellipse; the green's slope arrows, which the scene draws
// on the ground.
#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <vector>

#include "game/ui/clear_of.hpp"
#include "game/ui/golf_draw.hpp"
#include "physics/units.hpp"

namespace sweetspot {
namespace {

ImVec2 px(const Eigen::Vector2d& p) { return ImVec2(static_cast<float>(p(0)), static_cast<float>(p(1))); }

// A line from a to b with gaps where it crosses any of `boxes`: a flagstick drawn over the
// image must not strike through the image's own labels.
void line_clear_of(ImDrawList* dl, ImVec2 a, ImVec2 b, ImU32 colour, float thickness, const std::vector<Eigen::Vector4f>& boxes) {
  const auto at = [&](float t) { return ImVec2(a.x + t * (b.x - a.x), a.y + t * (b.y - a.y)); };
  for (const auto& [t0, t1] : parts_clear_of({a.x, a.y}, {b.x, b.y}, boxes)) dl->AddLine(at(t0), at(t1), colour, thickness);
}

// A line on the ground through `points`, projected; parts behind the camera skipped.
// `dashed`: every other segment only.
void ground_polyline(ImDrawList* dl, const Camera& cam, const std::vector<Vec3>& points, int w, int h, ImU32 colour,
                     float thickness, bool dashed = false) {
  for (std::size_t k = 0; k + 1 < points.size(); k += dashed ? 2 : 1) {
    const auto a = cam.project(points[k], w, h), b = cam.project(points[k + 1], w, h);
    if (a && b) dl->AddLine(px(*a), px(*b), colour, thickness);
  }
}

// The ground height under (x, z), or `fallback` off the world.
double ground_y(const WorldAsset& world, double x, double z, double fallback) {
  SurfaceContact hit;
  const WorldDescription& d = world.description();
  if (!ground_under(*world.world, x, z, d.bounds_max.y(), d.bounds_max.y() - d.bounds_min.y(), &hit)) return fallback;
  return hit.point.y();
}

}  // namespace

std::vector<SlopeArrow> green_slopes(const WorldAsset& w, const Vec3& ball, const Vec3& pin) {
  std::vector<SlopeArrow> out;
  const double length = std::hypot(pin.x() - ball.x(), pin.z() - ball.z());
  const Vec3 along = length > 1e-6 ? Vec3(Vec3(pin.x() - ball.x(), 0.0, pin.z() - ball.z()) / length) : Vec3(Vec3::UnitX());
  const Vec3 across(-along.z(), 0.0, along.x());
  // Six rows to the cup, never closer than 0.6 m (a putter head's length and a half) nor
  // wider than 2.5 m; the rows run past the cup as far as a missed putt of this length stops
  // (a quarter of it and half a metre, at most 2 m), where the slowing ball breaks most, and
  // no nearer the green camera behind the cup. Across, a quarter of the putt each side and a
  // metre: a green's 1-3 % breaks a putt by well under that. Nothing behind the ball (the
  // camera stands there, and the ball never rolls there), the first row half a step in front.
  const double step = std::clamp(length / 6.0, 0.6, 2.5);
  const double half_width = std::clamp(0.25 * length + 1.0, 1.2, 6.0);
  const double past = std::min(2.0, 0.25 * length + 0.5);
  const int columns = static_cast<int>(std::floor(half_width / step));
  for (double a = 0.5 * step; a <= length + past + 1e-9; a += step) {
    for (int c = -columns; c <= columns; ++c) {
      const Vec3 p = ball + a * along + (c * step) * across;
      SurfaceContact hit;
      if (!ground_under(*w.world, p.x(), p.z(), 400.0, 420.0, &hit)) continue;
      if (w.world->material(hit.material).kind != SurfaceKind::Green) continue;
      const Vec3& n = hit.normal;
      const Vec3 flat(n.x(), 0.0, n.z());
      out.push_back({hit.point, flat / std::max(n.y(), 1e-6), step});
    }
  }
  return out;
}

void draw_cup_and_flag(const Camera& cam, const Vec3& pin, int w, int h, bool scene_has_flag, const std::string& label,
                       const std::vector<Eigen::Vector4f>& clear_of) {
  ImDrawList* dl = ImGui::GetBackgroundDrawList();
  const auto base = cam.project(pin, w, h);
  if (!base) return;
  // The flagstick (kFlagstickHeight) with a flag at its top, drawn at least 40 px tall so a
  // pin 400 m away is still seen.
  const auto top = cam.project(pin + Vec3(0.0, kFlagstickHeight, 0.0), w, h);
  ImVec2 b = px(*base), t = top ? px(*top) : ImVec2(b.x, b.y - 40.0f);
  if (b.y - t.y < 40.0f) t = ImVec2(b.x, b.y - 40.0f);
  // The cup: 108 mm across (Rules of Golf, Definitions "Hole"), never under 5 px.
  const auto edge = cam.project(pin + Vec3(0.054, 0.0, 0.0), w, h);
  const float r = std::max(5.0f, edge ? std::abs(px(*edge).x - b.x) : 0.0f);
  ImVec2 rim[24];
  for (int k = 0; k < 24; ++k) {
    const float a = 6.2831853f * static_cast<float>(k) / 24.0f;
    rim[k] = ImVec2(b.x + r * std::cos(a), b.y + 0.45f * r * std::sin(a));
  }
  dl->AddConvexPolyFilled(rim, 24, IM_COL32(10, 10, 10, 255));
  // Near enough, the scene's own flagstick and wind-blown flag read on their own: a drawn
  // flag over them would show two flags, one of them pointing a way the wind does not blow.
  constexpr float kSceneFlagReadsPx = 24.0f;
  const float fh = 0.3f * (b.y - t.y);
  if (scene_has_flag && top && b.y - px(*top).y >= kSceneFlagReadsPx) {
    // Its cloth does; its 25 mm pole is under 2 px wide until ~15 m away at 800 lines and
    // drops out of the raster, leaving the cloth afloat over the cup: drawn 2 px wide then.
    constexpr float kPoleDiameterOverHeight = static_cast<float>(0.025 / kFlagstickHeight);  // assets/meshes/flag.obj
    if ((b.y - px(*top).y) * kPoleDiameterOverHeight < 2.0f) line_clear_of(dl, b, px(*top), IM_COL32(240, 240, 240, 255), 2.0f, clear_of);
    // Its label still says where the pin is: a cloth blown edge-on down the line is a pole
    // alone at 100 yd.
  } else {
    line_clear_of(dl, b, t, IM_COL32(240, 240, 240, 255), 2.0f, clear_of);
    // The cloth gives way to a label it would cover; the pole's top still marks the pin.
    if (!overlaps_any({t.x, t.y}, {t.x + 0.7f * fh, t.y + fh}, clear_of))
      dl->AddTriangleFilled(t, ImVec2(t.x + 0.7f * fh, t.y + 0.5f * fh), ImVec2(t.x, t.y + fh), IM_COL32(230, 40, 40, 255));
  }
  if (!label.empty()) {
    const ImVec2 size = ImGui::CalcTextSize(label.c_str());
    const auto clear = [&](const ImVec2& at) { return !overlaps_any({at.x, at.y}, {at.x + size.x, at.y + size.y}, clear_of); };
    // Beside the cloth; else beside the cup, under the flag (a flag just below the play panel).
    for (const ImVec2 at : {ImVec2(t.x + 0.7f * fh + 3.0f, t.y), ImVec2(b.x + r + 3.0f, b.y - 0.5f * size.y)}) {
      if (!clear(at)) continue;
      dl->AddText(ImVec2(at.x + 1.0f, at.y + 1.0f), IM_COL32(0, 0, 0, 200), label.c_str());  // a shadow over light sky
      dl->AddText(at, IM_COL32(255, 255, 255, 255), label.c_str());
      break;
    }
  }
}

void draw_aim(const GolfPlay& play, const Camera& cam, int w, int h) {
  const GolfRound& r = play.round();
  ImDrawList* dl = ImGui::GetBackgroundDrawList();
  const Vec3 b = play.ball_centre();
  // On the green the line runs a metre past the cup (the pace a putt should carry), except
  // toward an eye standing beyond the cup on the line, where that metre would point at the
  // viewer and fill the foreground.
  const Vec3 aim = play.aim_direction();
  const bool eye_past_cup = (cam.eye - b).dot(aim) > r.to_pin();
  const double len = r.lie() != "green" ? std::min(r.to_pin(), 250.0) : r.to_pin() + (eye_past_cup ? 0.0 : 1.0);
  const auto p0 = cam.project(b, w, h), p1 = cam.project(b + len * aim, w, h);
  if (p0 && p1) dl->AddLine(px(*p0), px(*p1), IM_COL32(255, 255, 255, 170), 2.0f);
}

namespace {
// `f(name, ball)` for each other player with a ball in play on the hole being played.
template <class F>
void for_each_other_ball(const GolfPlay& play, F f) {
  const GolfGroup& g = play.group();
  const GolfRound& r = play.round();
  for (std::size_t p = 0; p < g.players().size(); ++p) {
    if (static_cast<int>(p) == play.player()) continue;
    const GolfRound& o = g.round(static_cast<int>(p));
    if (o.finished() || o.hole_index() != r.hole_index() || o.card().back().shots.empty()) continue;
    f(g.players()[p].name, o.ball());
  }
}
}  // namespace

void draw_other_balls(const GolfPlay& play, const Camera& cam, int w, int h, const std::vector<Eigen::Vector4f>& clear_of) {
  ImDrawList* dl = ImGui::GetBackgroundDrawList();
  for_each_other_ball(play, [&](const std::string& name, const Vec3& ball) {
    const double radius = 0.02134;  // m: a golf ball at the Rules of Golf's least, 42.67 mm across
    const Vec3 centre = ball + Vec3(0.0, radius, 0.0);
    const auto at = cam.project(centre, w, h), edge = cam.project(centre + radius * cam.true_up(), w, h);
    if (!at || at->x() < 0.0 || at->x() > w || at->y() < 0.0 || at->y() > h) return;
    // Its true size near, never under 3 px far off, so it is found.
    const float rad = std::max(3.0f, edge ? static_cast<float>((*at - *edge).norm()) : 0.0f);
    const ImVec2 c = px(*at);
    dl->AddCircleFilled(c, rad, IM_COL32(245, 245, 245, 255));
    dl->AddCircle(c, rad, IM_COL32(0, 0, 0, 200), 0, 1.0f);
    const ImVec2 size = ImGui::CalcTextSize(name.c_str());
    const ImVec2 label(c.x + rad + 4.0f, c.y - 0.5f * size.y);
    if (overlaps_any({label.x, label.y}, {label.x + size.x, label.y + size.y}, clear_of)) return;
    dl->AddText(ImVec2(label.x + 1.0f, label.y + 1.0f), IM_COL32(0, 0, 0, 200), name.c_str());
    dl->AddText(label, IM_COL32(235, 235, 235, 255), name.c_str());
  });
}

void draw_putt_read(const GolfPlay& play, const Camera& cam, int w, int h) {
  const auto& read = play.putt_read();
  if (!read) return;
  // Dotted along the ball's centre (21 mm above the grass), in the caddie's blue as his pace
  // mark on the meter: every other 5 cm step drawn.
  ground_polyline(ImGui::GetBackgroundDrawList(), cam, read->line, w, h, IM_COL32(120, 220, 255, 230), 3.0f, true);
}

std::vector<GroundArrow> slope_arrows(const std::vector<SlopeArrow>& slopes) {
  std::vector<GroundArrow> out;
  for (const SlopeArrow& a : slopes) {
    // The arrow points downhill; its length and colour grow with the slope (white flat, red
    // at 4 %, steep for a green: USGA greens run 1-3 % where cups are cut).
    const double s = a.downhill.norm();
    if (s < 1e-4) continue;
    const Vec3 dir = a.downhill / s;
    const double steep = std::clamp(s / 0.04, 0.0, 1.0);
    // Never longer than 80 % of its room, so neighbours never run into each other, nor than
    // 1.2 m: on a long putt's wide grid the rows nearest the camera would fill the picture.
    constexpr double kLongest = 1.2;  // m
    const double len_m = std::min(kLongest, a.room * (0.35 + 0.45 * steep));
    const float red = static_cast<float>(steep);
    out.push_back({a.at - 0.5 * len_m * dir, a.at + 0.5 * len_m * dir, Eigen::Vector3f(1.0f, 1.0f - 0.75f * red, 1.0f - red)});
  }
  return out;
}

void draw_map_marks(const GolfPlay& play, const GolfUnits& units, const Camera& cam, int w, int h,
                    const std::vector<TreeCrown>& crowns, const std::vector<Eigen::Vector4f>& clear_of) {
  const GolfRound& r = play.round();
  if (r.finished()) return;
  ImDrawList* dl = ImGui::GetBackgroundDrawList();
  // The trees as a map shows them, a dark disc with a rim for each crown: seen from above a
  // crown's shaded green reads as more rough. Under every other mark.
  for (const TreeCrown& c : crowns) {
    const auto at = cam.project(c.centre, w, h);
    if (!at || at->x() < -50.0 || at->y() < -50.0 || at->x() > w + 50.0 || at->y() > h + 50.0) continue;
    const float radius = static_cast<float>(std::max(2.0, c.radius / cam.metres_per_pixel(c.centre, h)));
    dl->AddCircleFilled(px(*at), radius, IM_COL32(16, 52, 20, 235), 12);
    dl->AddCircle(px(*at), radius, IM_COL32(8, 26, 10, 255), 12, 1.0f);
  }
  const WorldAsset& world = *r.hole().world;
  const Vec3 ball = r.ball();
  const Vec3 aim = play.aim_direction();
  const Vec3 side(-aim.z(), 0.0, aim.x());
  const std::string& club = play.club();
  // The selected club's full-swing carry from here (the wind, the lie: the panel's "from here"
  // figure, so the ring and the panel agree); its spread the caddie's stock (the player's bag
  // when they measured one).
  // The caddie's part swing with this club (a pitch, a chip) is drawn instead, with its own
  // spread: a full swing's ring 77 yd out says nothing of a 37 yd pitch.
  const double part = club != "putter" ? play.caddie_part_swing(club).value_or(1.0) : 1.0;
  const GolfBot::Stock* stock = part < 1.0 ? nullptr : play.caddie().stock_of(club);
  const double carry = club == "putter" ? r.to_pin() : play.carry_here(club, part);
  double spread = stock ? stock->spread : 0.0, side_spread = stock ? stock->side_spread : 0.0;
  // The player's own dispersion with this club this round, when they have hit it twice with a
  // full swing (a part swing's carry is another club's: it would smear the spread).
  constexpr double kFullSwing = 0.9;
  int n = 0;
  double sum = 0.0, sum2 = 0.0, side2 = 0.0;
  for (const HoleCard& c : r.card())
    for (const StrokeRecord& s : c.shots)
      if (part >= 1.0 && s.club == club && !s.conceded && s.carry_m > 0.0 && s.power >= kFullSwing) {
        ++n;
        sum += s.carry_m;
        sum2 += s.carry_m * s.carry_m;
        side2 += s.side_m * s.side_m;
      }
  std::string whose = spread > 0.0 ? "your spread (your bag)" : "";
  if (n >= 2) {
    const double mean = sum / n;
    spread = std::sqrt(std::max(0.0, (sum2 - n * mean * mean) / (n - 1)));
    side_spread = std::sqrt(side2 / n);
    whose = "your spread (this round)";
  } else if (spread <= 0.0) {
    // Before the player's own: a golfer of his skill's, by the meter errors the bots of that
    // skill make, so a newcomer's map has the ellipse too (and says whose it is).
    if (const auto prior = play.skill_spread(club, part)) {
      spread = prior->carry_sd;
      side_spread = prior->side_sd;
      const std::string& skill = play.skill().name;
      whose = (std::string("aeiou").find(skill.empty() ? 'x' : skill[0]) != std::string::npos ? "an " : "a ") + skill + " golfer's spread";
      if (part < 1.0) whose += " (part swing)";
    }
  }
  auto on_ground = [&](double along, double across) {
    const Vec3 p = ball + along * aim + across * side;
    return Vec3(p.x(), ground_y(world, p.x(), p.z(), ball.y()) + 0.3, p.z());
  };
  // Labels already drawn (their boxes, px), so a later one steps aside instead of over them:
  // the image's own (the distance stripes' numbers) first.
  std::vector<std::pair<ImVec2, ImVec2>> taken;
  for (const Eigen::Vector4f& b : clear_of) taken.emplace_back(ImVec2(b[0], b[1]), ImVec2(b[2], b[3]));
  const auto place = [&](ImVec2 at, const std::string& text, ImVec2 dot) {
    const ImVec2 size = ImGui::CalcTextSize(text.c_str());
    const auto overlaps = [&](ImVec2 a) {
      for (const auto& [lo, hi] : taken)
        if (a.x < hi.x && a.x + size.x > lo.x && a.y < hi.y && a.y + size.y > lo.y) return true;
      return false;
    };
    // Right of its mark, else left of it, else below or above it, else a line further down
    // each time: the first place clear of every label already there.
    const ImVec2 tries[] = {at,
                            ImVec2(dot.x - size.x - 6.0f, at.y),
                            ImVec2(dot.x - 0.5f * size.x, dot.y + 8.0f),
                            ImVec2(dot.x - 0.5f * size.x, dot.y - 8.0f - size.y),
                            ImVec2(dot.x + 6.0f, dot.y + 8.0f + size.y),
                            ImVec2(dot.x + 6.0f, dot.y + 8.0f + 2.0f * size.y),
                            ImVec2(dot.x + 6.0f, dot.y - 8.0f - 2.0f * size.y)};
    // Whole on the screen too (a label out to the right of a small window was cut off);
    // where no place is both, the first clear one moved onto the screen.
    const auto on_screen = [&](ImVec2 a) {
      return a.x >= 0.0f && a.y >= 0.0f && a.x + size.x <= static_cast<float>(w) && a.y + size.y <= static_cast<float>(h);
    };
    const auto onto_screen = [&](ImVec2 a) {
      return ImVec2(std::clamp(a.x, 0.0f, std::max(0.0f, static_cast<float>(w) - size.x)),
                    std::clamp(a.y, 0.0f, std::max(0.0f, static_cast<float>(h) - size.y)));
    };
    std::optional<ImVec2> chosen, clear;
    for (const ImVec2& t : tries) {
      if (overlaps(t)) continue;
      if (!clear) clear = t;
      if (on_screen(t)) {
        chosen = t;
        break;
      }
    }
    const ImVec2 at_last = chosen ? *chosen : onto_screen(clear ? *clear : at);
    taken.emplace_back(at_last, ImVec2(at_last.x + size.x, at_last.y + size.y));
    return at_last;
  };
  // The carry ring: a circle of the carry around the ball.
  if (carry > 1.0) {
    std::vector<Vec3> ring;
    for (int k = 0; k <= 72; ++k) {
      const double a = 2.0 * kPi * k / 72.0;
      ring.push_back(on_ground(carry * std::cos(a), carry * std::sin(a)));
    }
    ground_polyline(dl, cam, ring, w, h, IM_COL32(255, 230, 90, 220), 2.0f);
    if (const auto lp = cam.project(on_ground(carry, 0.0), w, h)) {
      // A putt's ring in the putt's units, as the panel says its distance ("putter 18 ft"); a
      // part swing's in the unit the panel gives its carry and stop in, "To the pin"'s
      // ("carries 12 yd" from 25 yd, not "37 ft" here); a full swing's as the launch monitor
      // will say it.
      const double longest = part < 1.0 ? play.round().to_pin() : carry;
      const std::string text =
          club + " " + (club == "putter" ? units.putt(carry) : units.course(carry, longest)) + (part < 1.0 ? ", part swing" : "");
      dl->AddText(place(ImVec2(px(*lp).x + 6, px(*lp).y - 18), text, px(*lp)), IM_COL32(255, 230, 90, 255), text.c_str());
    }
  }
  // The dispersion: an ellipse of two standard deviations (about 86 % of shots) around where
  // the swing comes down: the wind's drift and the curve taken, not on the aim line (aimed
  // 27 yd left of a pin in a crosswind, the ball comes back to it).
  if (carry > 1.0 && spread > 0.0 && club != "putter") {
    const Vec3 landing = play.landing_here(club, part) - ball;
    const double along = landing.x() * aim.x() + landing.z() * aim.z(), across = landing.x() * side.x() + landing.z() * side.z();
    std::vector<Vec3> ellipse;
    for (int k = 0; k <= 48; ++k) {
      const double a = 2.0 * kPi * k / 48.0;
      ellipse.push_back(on_ground(along + 2.0 * spread * std::cos(a), across + 2.0 * std::max(side_spread, 1.0) * std::sin(a)));
    }
    ground_polyline(dl, cam, ellipse, w, h, IM_COL32(120, 200, 255, 230), 2.0f);
    if (const auto lp = cam.project(on_ground(along - 2.0 * spread, across), w, h)) {
      const std::string& text = whose;
      dl->AddText(place(ImVec2(px(*lp).x + 6, px(*lp).y + 4), text, px(*lp)), IM_COL32(120, 200, 255, 255), text.c_str());
    }
  }
  // The ball, big enough to find.
  if (const auto bp = cam.project(on_ground(0.0, 0.0), w, h)) {
    dl->AddCircleFilled(px(*bp), 6.0f, IM_COL32(255, 255, 255, 255));
    dl->AddCircle(px(*bp), 6.0f, IM_COL32(0, 0, 0, 255), 0, 1.5f);
  }
  // The other players' balls on this hole.
  for_each_other_ball(play, [&](const std::string& name, const Vec3& ball) {
    if (const auto op = cam.project(ball + Vec3(0, 0.3, 0), w, h)) {
      dl->AddCircleFilled(px(*op), 4.0f, IM_COL32(200, 200, 200, 230));
      dl->AddText(place(ImVec2(px(*op).x + 6, px(*op).y - 6), name, px(*op)), IM_COL32(220, 220, 220, 255), name.c_str());
    }
  });
}

}  // namespace sweetspot
