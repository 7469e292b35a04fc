#include "game/modes/baseball/figures.hpp"

#include <algorithm>
#include <cmath>

#include "game/modes/baseball/pitcher.hpp"

namespace sweetspot {
namespace {

// Body proportions of a 1.88 m player (ESTIMATES from standard anthropometric ratios).
constexpr double kHipHeight = 0.98, kShoulderHeight = 1.52, kNeckHeight = 1.62, kHeadHeight = 1.78;
constexpr double kHipHalf = 0.14, kShoulderHalf = 0.2, kUpperArm = 0.32, kForearm = 0.3, kThigh = 0.47;  // shin = thigh
constexpr double kBatLength = 0.84;  // m, the maple bat

double smooth(double x) {
  x = std::clamp(x, 0.0, 1.0);
  return x * x * (3.0 - 2.0 * x);
}

// A pose built in the figure's own frame (x forward, y up, z to his right) and placed in the world.
struct Frame {
  Vec3 origin;
  double yaw;  // rad: his forward turned from world +x toward +z
  Vec3 operator()(double fx, double fy, double fz) const {
    const double c = std::cos(yaw), s = std::sin(yaw);
    return origin + Vec3(fx * c - fz * s, fy, fx * s + fz * c);
  }
};

// The knee between a hip and a foot, bent forward (+`forward` direction) by the leg's length.
Vec3 knee_between(const Vec3& hip, const Vec3& foot, const Vec3& forward) {
  const Vec3 mid = 0.5 * (hip + foot);
  const double half = 0.5 * (hip - foot).norm();
  const double bend = std::sqrt(std::max(0.0, kThigh * kThigh - half * half));
  Vec3 f = forward - forward.dot((hip - foot).normalized()) * (hip - foot).normalized();
  if (f.norm() < 1e-9) f = Vec3::UnitX();
  return mid + bend * f.normalized();
}

// The elbow between a shoulder and a hand, bent toward `out`.
Vec3 elbow_between(const Vec3& shoulder, const Vec3& hand, const Vec3& out) {
  const Vec3 mid = 0.5 * (shoulder + hand);
  const double half = 0.5 * (shoulder - hand).norm();
  const double bend = std::sqrt(std::max(0.0, 0.25 * (kUpperArm + kForearm) * (kUpperArm + kForearm) - half * half));
  const Vec3 axis = (hand - shoulder).norm() > 1e-9 ? (hand - shoulder).normalized() : Vec3::UnitY();
  Vec3 o = out - out.dot(axis) * axis;
  if (o.norm() < 1e-9) o = Vec3::UnitY();
  return mid + bend * o.normalized();
}

void fill_limbs(Figure& f, const Frame& fr, const Vec3& left_foot, const Vec3& right_foot, const Vec3& left_hand,
                const Vec3& right_hand, double crouch, double twist) {
  const Frame body{fr.origin, fr.yaw + twist};
  f.joint[kPelvis] = fr(0.0, kHipHeight - crouch, 0.0);
  f.joint[kNeck] = body(0.0, kNeckHeight - crouch, 0.0);
  f.joint[kHead] = body(0.0, kHeadHeight - crouch, 0.0);
  f.joint[kLeftShoulder] = body(0.0, kShoulderHeight - crouch, -kShoulderHalf);
  f.joint[kRightShoulder] = body(0.0, kShoulderHeight - crouch, kShoulderHalf);
  f.joint[kLeftHip] = fr(0.0, kHipHeight - crouch, -kHipHalf);
  f.joint[kRightHip] = fr(0.0, kHipHeight - crouch, kHipHalf);
  f.joint[kLeftFoot] = left_foot;
  f.joint[kRightFoot] = right_foot;
  f.joint[kLeftHand] = left_hand;
  f.joint[kRightHand] = right_hand;
  const Vec3 forward = fr(1.0, 0.0, 0.0) - fr.origin;
  f.joint[kLeftKnee] = knee_between(f.joint[kLeftHip], left_foot, forward);
  f.joint[kRightKnee] = knee_between(f.joint[kRightHip], right_foot, forward);
  f.joint[kLeftElbow] = elbow_between(f.joint[kLeftShoulder], left_hand, fr(0.0, -1.0, -1.0) - fr.origin);
  f.joint[kRightElbow] = elbow_between(f.joint[kRightShoulder], right_hand, fr(0.0, -1.0, 1.0) - fr.origin);
}

Figure mirror_z(Figure f) {
  for (Vec3& p : f.joint) p.z() = -p.z();
  std::swap(f.joint[kLeftShoulder], f.joint[kRightShoulder]);
  std::swap(f.joint[kLeftElbow], f.joint[kRightElbow]);
  std::swap(f.joint[kLeftHand], f.joint[kRightHand]);
  std::swap(f.joint[kLeftHip], f.joint[kRightHip]);
  std::swap(f.joint[kLeftKnee], f.joint[kRightKnee]);
  std::swap(f.joint[kLeftFoot], f.joint[kRightFoot]);
  return f;
}

}  // namespace

const std::vector<std::pair<Joint, Joint>>& figure_bones() {
  static const std::vector<std::pair<Joint, Joint>> b = {
      {kHead, kNeck},           {kNeck, kPelvis},         {kLeftShoulder, kRightShoulder}, {kLeftShoulder, kLeftElbow},
      {kLeftElbow, kLeftHand},  {kRightShoulder, kRightElbow}, {kRightElbow, kRightHand},  {kLeftHip, kRightHip},
      {kLeftHip, kLeftKnee},    {kLeftKnee, kLeftFoot},   {kRightHip, kRightKnee},         {kRightKnee, kRightFoot},
      {kBatKnob, kBatTip}};
  return b;
}

Figure pitcher_figure(const Vec3& release, double t, bool left_handed) {
  // Built for a right-hander facing home (−x) from the rubber; a left-hander is its mirror.
  const Vec3 rel = left_handed ? Vec3(release.x(), release.y(), -release.z()) : release;
  const double rubber = 18.44;
  const double stride = std::max(0.0, rubber - rel.x() - 0.2);  // his front foot lands short of the release
  const Frame fr{Vec3(rubber - smooth((t + 0.5) / 0.45) * 0.6 * stride, 0.0, 0.0), kPi};  // facing −x
  Figure f;
  // Phases: set (hands at the chest), leg lift, stride, release, follow-through.
  const double lift = smooth((t + kWindupTime) / 0.35) * (1.0 - smooth((t + 0.45) / 0.3));
  const double go = smooth((t + 0.45) / 0.45);  // the stride and the arm coming through
  const double after = smooth(t / 0.35);
  // Feet: the back (right) foot on the rubber, the front (left) foot lifts, then strides toward home.
  const Vec3 back_foot = Vec3(rubber, 0.0, 0.12) + after * Vec3(-0.9, 0.1, -0.2);
  const Vec3 front_foot = Vec3(rubber - go * stride, 0.45 * lift, -0.15 + 0.1 * go);
  // The throwing hand: at the chest, back and up behind the head, then out to the release
  // point, then down across the body.
  const Vec3 chest = fr(0.25, 1.25, 0.0);
  const Vec3 cocked = Vec3(rubber + 0.55, 1.85, 0.45);
  Vec3 throw_hand = chest;
  if (t < -0.45) throw_hand = chest;
  else if (t < -0.12) throw_hand = chest + smooth((t + 0.45) / 0.33) * (cocked - chest);
  else if (t < 0.0) throw_hand = cocked + smooth((t + 0.12) / 0.12) * (rel - cocked);
  else throw_hand = rel + after * (Vec3(rel.x() - 0.6, 0.7, -0.35) - rel);
  const Vec3 glove = t < -0.45 ? chest + Vec3(0.0, 0.0, -0.05) : fr(0.5, 1.35 - 0.3 * go, -0.35 + 0.2 * go);
  fill_limbs(f, fr, front_foot, back_foot, glove, throw_hand, 0.12 * go, 0.0);
  return left_handed ? mirror_z(f) : f;
}

Figure batter_figure(double phase, double bat_height, bool left_handed) {
  // A right-hander in the box on the third-base side (−z), facing the plate (+z), his front
  // (left) shoulder toward the pitcher (+x).
  const Frame fr{Vec3(0.0, 0.0, -0.75), 0.5 * kPi};  // forward = +z
  Figure f;
  f.has_bat = true;
  const double stride = smooth(phase / 0.6);  // the front foot strides toward the pitcher
  const Vec3 front_foot = Vec3(0.25 + 0.25 * stride, 0.0, -0.75);
  const Vec3 back_foot = Vec3(-0.45, 0.0, -0.8 + 0.1 * smooth(phase - 0.6));
  // The bat turns about the hands as the hips and shoulders open: its angle about the
  // vertical from pointing back over his shoulder (stance) through square (contact) around
  // to his front (follow-through). Through the stride (phase to 0.6) it stays loaded: a
  // batter who takes the pitch strides and holds, and the swing is the last 0.4 (turned
  // over the whole 0 to 1, the bat was level and two-thirds round as a taken pitch arrived,
  // a swing to a player's eye).
  const double swing = phase < 0.6 ? 0.0 : smooth((phase - 0.6) / 0.4);  // 0 loaded .. 1 contact
  const double turn = phase < 1.0 ? -0.5 * kPi * (1.0 - swing) : 0.8 * kPi * smooth((phase - 1.0) / 0.6);
  const double hands_y = phase < 1.0 ? kStanceHandsHigh - (kStanceHandsHigh - bat_height) * swing
                                     : bat_height + 0.9 * smooth((phase - 1.0) / 0.6);
  const Vec3 hands(0.05 + 0.35 * (phase < 1.0 ? swing : 1.0), hands_y, -kStanceHandsFromMiddle);
  // The bat's direction: up and back in the stance, level and square (along +z) at contact.
  const double tilt = phase < 1.0 ? (1.0 - swing) * 1.1 : 0.0;
  const Vec3 stance = Vec3(-0.35, 0.9, 0.2).normalized();
  const Vec3 swung(std::sin(turn) * std::cos(tilt), std::sin(tilt) * 1.0, std::cos(turn) * std::cos(tilt));
  const Vec3 dir = phase < 1.0 ? Vec3((1.0 - swing) * stance + swing * swung.normalized()) : swung;
  f.joint[kBatKnob] = hands;
  f.joint[kBatTip] = hands + kBatLength * dir.normalized();
  fill_limbs(f, fr, front_foot, back_foot, hands + Vec3(0.04, 0.0, 0.0), hands - Vec3(0.04, 0.0, 0.0), 0.1, 0.0);
  return left_handed ? mirror_z(f) : f;
}

Vec3 fielder_position(const Vec3& start, const Vec3& goal, const FielderAbility& a, double t) {
  const Vec3 d(goal.x() - start.x(), 0.0, goal.z() - start.z());
  const double dist = d.norm();
  if (dist < 1e-9 || t <= a.reaction) return start;
  const double run = t - a.reaction;
  const double t_acc = a.sprint / a.accel;
  const double covered = run <= t_acc ? 0.5 * a.accel * run * run : 0.5 * a.sprint * t_acc + a.sprint * (run - t_acc);
  return start + std::min(covered, dist) / dist * d;
}

Figure fielder_figure(const Vec3& start, const Vec3& goal, const FielderAbility& a, double t, bool catcher,
                      const std::optional<Vec3>& glove) {
  const Vec3 at = fielder_position(start, goal, a, t);
  const Vec3 d = goal - start;
  const bool moving = t > a.reaction && (goal - at).norm() > 0.05;
  // Facing home until he runs, then along his run.
  const double yaw = moving ? std::atan2(d.z(), d.x()) : std::atan2(-start.z(), -start.x());
  const Frame fr{Vec3(at.x(), 0.0, at.z()), yaw};
  Figure f;
  double crouch = catcher && !moving ? 0.45 : moving ? 0.05 : 0.15;
  // A ball below his waist he bends for, down to a crouch (ESTIMATE: the glove at ~0.7 m
  // standing).
  if (glove) crouch = std::max(crouch, std::clamp(0.7 - glove->y(), 0.0, 0.5));
  // Running: the legs and arms swing at ~2.2 strides a second (ESTIMATE of a sprinter's cadence).
  const double swing = moving ? std::sin(2.0 * kPi * 2.2 * t) : 0.0;
  const Vec3 lf = fr(0.35 * swing, moving ? 0.15 * std::max(0.0, -swing) : 0.0, -0.18);
  const Vec3 rf = fr(-0.35 * swing, moving ? 0.15 * std::max(0.0, swing) : 0.0, 0.18);
  Vec3 lh = fr(-0.3 * swing + (moving ? 0.0 : 0.3), 1.0 - crouch, -0.3);
  if (glove) {
    const Vec3 shoulder = fr(0.0, kShoulderHeight - crouch, -kShoulderHalf);
    const Vec3 to = *glove - shoulder;
    const double arm = kUpperArm + kForearm;
    lh = shoulder + (to.norm() > arm ? Vec3(to.normalized() * arm) : to);
  }
  const Vec3 rh = fr(0.3 * swing + (moving ? 0.0 : 0.3), 1.0 - crouch, 0.3);
  fill_limbs(f, fr, lf, rf, lh, rh, crouch, 0.0);
  return f;
}

}  // namespace sweetspot
