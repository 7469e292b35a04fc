// Swing + pitch -> contact state -> impulse -> launch. See delivery.hpp.
//
// Golf: the head is a free rigid body for the ~0.5 ms contact (the shaft is ignored, as
// the hands and shaft cannot transmit a significant impulse in that time). Its pose comes
// from the dynamic loft (rotation about the toe axis) and the face angle (about vertical);
// the lie is taken as delivered correctly (sole level at impact), so it only sets the
// shaft axis the closure rate turns about. The face is the paraboloid
//   x = -(z² / 2R_bulge + y² / 2R_roll)   (head frame),
// so an offset hit meets a face whose normal is tilted toward the offset by the bulge and
// roll curvature. Gear effect then follows from the head's CG offset and full inertia
// tensor inside the collision matrix.
//
// Baseball: the bat is a rigid body turning about a pivot near the knob (the swing's
// instantaneous centre of rotation), free during the ~1 ms contact. The normal runs from
// the bat axis to the ball centre, so undercut tilts it up (backspin, loft).
#include "physics/delivery.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>
#include <string>

#include "physics/body.hpp"
#include "physics/error.hpp"

namespace sweetspot {

namespace {

Quat axis_angle(double angle, const Vec3& axis) { return Quat(Eigen::AngleAxisd(angle, axis)); }

LaunchState launch_of(const ImpactResult& r, const Vec3& ball_centre) {
  LaunchState l;
  l.position = ball_centre;
  l.velocity = r.ball_after.velocity;
  l.spin = r.ball_after.angular_velocity;
  return l;
}

// The least closing speed that is a strike, as a share of the contact's speed: the surface
// moving within 1° of its own plane only grazes the ball (a 90° spin loft, a bat swung
// along the ball's side). sin 1° = 0.0175 leaves a ball of ~2 % of the club's speed, the
// slowest a launch monitor would read as a shot; anything less is a whiff.
constexpr double kGrazeShare = 0.0175;

// Far off-centre contact with a slow swing, or a face laid open to the swing's direction,
// can leave the striking surface moving along or away from the contact normal: a geometric
// miss, which deserves words a player understands rather than a 0 mph "shot".
void refuse_miss(const Delivery& d, const char* who) {
  const Vec3 u = contact_velocity(d.impact_input.impactor, d.impact_input.ball);
  const double closing = -u.dot(d.impact_input.normal);
  if (closing > kGrazeShare * u.norm() && closing > 1e-3) return;
  std::ostringstream os;
  os << who << ": the strike misses: at this contact point the " << (std::string(who).starts_with("golf") ? "club" : "bat")
     << " does not close on the ball (closing speed " << closing << " m/s along the contact normal, of "
     << u.norm() << " m/s; a strike needs at least " << kGrazeShare
     << " of it, the surface moving more than 1 deg out of its own plane); hit nearer the centre, "
        "swing faster or present less loft to the swing";
  throw InputError(os.str());
}

void solve_into(Delivery& d, const char* who) {
  refuse_miss(d, who);
  if (auto msg = validate_impact(d.impact_input); !msg.empty()) {
    throw InputError(std::string(who) + ": " + msg);
  }
  d.impact = solve_impact(d.impact_input);
}


void solve_compliant_into(Delivery& d, CompliantImpactInput& in, const char* who) {
  refuse_miss(d, who);
  if (auto msg = validate_compliant_impact(in); !msg.empty()) throw InputError(std::string(who) + ": " + msg);
  const CompliantImpactResult r = solve_compliant_impact(in);
  ImpactResult& out = d.impact;
  out.impulse = r.impulse;
  out.normal_impulse = r.normal_impulse;
  out.tangential_impulse = r.tangential_impulse;
  out.e_used = r.e_used;
  out.contact = r.contact;
  out.energy_loss = r.energy_loss;
  out.impactor_after = d.impact_input.impactor;
  out.impactor_after.velocity = r.impactor_after.velocity;
  out.impactor_after.angular_velocity = r.impactor_after.angular_velocity;
  out.ball_after = d.impact_input.ball;
  out.ball_after.velocity = r.ball_after.velocity;
  out.ball_after.angular_velocity = r.ball_after.angular_velocity;
  // The tangential restitution the contact produced, in the instantaneous model's terms:
  // the contact point's tangential velocity after, against before, at the first touch.
  const Vec3& n = d.impact_input.normal;
  const Vec3 u0 = contact_velocity(d.impact_input.impactor, d.impact_input.ball);
  const Vec3 u1 = contact_velocity(out.impactor_after, out.ball_after);
  const Vec3 ut0 = u0 - u0.dot(n) * n;
  out.e_t_used = ut0.norm() > 1e-9 ? -(u1 - u1.dot(n) * n).dot(ut0) / ut0.squaredNorm() : 0.0;
  d.compliant = true;
  d.contact_time = r.duration;
  d.impactor_separated = r.impactor_after;
  d.ball_separated = r.ball_after;
}

/// The bodies at first touch, and at separation for the instantaneous impulse (same poses,
/// new velocities); the compliant solve has already set its own separated poses.
void record_bodies(Delivery& d, const RigidBody& impactor, const RigidBody& ball) {
  d.impactor_before = impactor;
  d.ball_before = ball;
  if (d.compliant) return;
  d.impactor_separated = impactor;
  d.impactor_separated.velocity = d.impact.impactor_after.velocity;
  d.impactor_separated.angular_velocity = d.impact.impactor_after.angular_velocity;
  d.ball_separated = ball;
  d.ball_separated.velocity = d.impact.ball_after.velocity;
  d.ball_separated.angular_velocity = d.impact.ball_after.angular_velocity;
}

}  // namespace

void validate_golf_swing(const GolfSwing& w, const ClubSpec& club) {
  check_range("swing.speed", w.club_speed, GolfSwing::kClubSpeed, "m/s");
  check_range("swing.attack_angle", w.attack_angle, GolfSwing::kAttackAngle, "rad");
  check_range("swing.path", w.club_path, GolfSwing::kClubPath, "rad");
  check_range("swing.face_angle", w.face_angle, GolfSwing::kFaceAngle, "rad");
  const double up = strike_up(w, club);
  check_range("swing.impact_offset[0] (toe)", w.impact_toe, GolfSwing::kImpactToe, "m");
  check_range("swing.impact_offset[1] (up)", up, GolfSwing::kImpactUp, "m");
  // And on this club's face: a putter's is 24 mm tall, an iron's 76 x 46 mm (face_size).
  const Range toe_on_face{-club.face_half_width, club.face_half_width};
  const Range up_on_face{-club.face_half_height, club.face_half_height};
  check_range("swing.impact_offset[0] (toe) on the " + club.name + "'s face", w.impact_toe, toe_on_face, "m");
  check_range("swing.impact_offset[1] (up) on the " + club.name + "'s face", up, up_on_face, "m");
  check_range("swing.closure_rate", w.closure_rate, GolfSwing::kClosureRate, "rad/s");
  check_range("swing.sand_entry", w.sand_entry, kSandEntry, "m");
  // The loft last: a loft given at the strike is checked where the strike (checked above)
  // puts the face centre, and named as given.
  if (!std::isnan(w.dynamic_loft) && !std::isnan(w.strike_loft))
    throw InputError(std::string("swing.strike_loft: ") + kLoftGivenTwice);
  if (std::isnan(w.strike_loft)) {
    check_range("swing.dynamic_loft", face_centre_loft(w, club), GolfSwing::kDynamicLoft, "rad");
  } else {
    const double tilt = strike_tilt(club, up);
    const Range at_strike{GolfSwing::kDynamicLoft.min + tilt, GolfSwing::kDynamicLoft.max + tilt};
    char why[96];
    std::snprintf(why, sizeof why, "swing.strike_loft (the %s's face tilts %.1f deg at this strike)", club.name.c_str(),
                  rad_to_deg(tilt));
    check_range(why, w.strike_loft, at_strike, "rad");
  }
  // The face angle likewise, after the loft it turns with.
  if (!std::isnan(w.strike_face_angle)) {
    if (w.face_angle != 0.0) throw InputError(std::string("swing.strike_face_angle: ") + kFaceAngleGivenTwice);
    const double turn = strike_turn(club, face_centre_loft(w, club), w.impact_toe, up);
    const Range at_strike{GolfSwing::kFaceAngle.min + turn, GolfSwing::kFaceAngle.max + turn};
    char why[104];
    std::snprintf(why, sizeof why, "swing.strike_face_angle (the %s's face turns %.1f deg at this strike)",
                  club.name.c_str(), rad_to_deg(turn));
    check_range(why, w.strike_face_angle, at_strike, "rad");
  }
}

double strike_tilt(const ClubSpec& club, double up) { return std::atan(up / club.roll_radius); }

double strike_turn(const ClubSpec& club, double centre_loft, double toe, double up) {
  // The head frame's normal at the strike, pitched by the loft about the toe axis (z): its
  // toe component is unchanged, its forward one becomes cos L - sin L · up/R_roll.
  return std::atan2(toe / club.bulge_radius, std::cos(centre_loft) - std::sin(centre_loft) * up / club.roll_radius);
}

double face_centre_face_angle(const GolfSwing& swing, const ClubSpec& club) {
  if (std::isnan(swing.strike_face_angle)) return swing.face_angle;
  const double up = strike_up(swing, club);
  return swing.strike_face_angle - strike_turn(club, face_centre_loft(swing, club), swing.impact_toe, up);
}

Vec3 head_direction(const GolfSwing& swing) {
  const double ca = std::cos(swing.attack_angle);
  return Vec3(ca * std::cos(swing.club_path), std::sin(swing.attack_angle), ca * std::sin(swing.club_path));
}

double face_centre_loft(const GolfSwing& swing, const ClubSpec& club) {
  if (!std::isnan(swing.dynamic_loft)) return swing.dynamic_loft;
  if (std::isnan(swing.strike_loft)) return club.dynamic_loft;
  const double up = strike_up(swing, club);
  return swing.strike_loft - strike_tilt(club, up);
}

double bat_ball_reach(const BatSpec& bat, const BallSpec& ball, double from_tip) {
  if (from_tip >= 0.0) return bat.radius_at(bat.length - from_tip) + ball.radius;
  const double over = std::min(-from_tip, ball.radius);
  return bat.radius_at(bat.length) + std::sqrt(ball.radius * ball.radius - over * over);
}

Range bat_contact_range(const BatSpec& bat, const BallSpec& ball) {
  return Range{-kEndCapReach * ball.radius, bat.pivot_to_tip() - 0.05};
}

void validate_bat_swing(const BatSwing& w, const BatSpec& bat, const BallSpec& ball) {
  check_range("swing.speed", w.bat_speed, BatSwing::kBatSpeed, "m/s");
  check_range("swing.attack_angle", w.attack_angle, BatSwing::kAttackAngle, "rad");
  check_range("swing.direction", w.direction, BatSwing::kDirection, "rad");
  check_range("swing.vertical_bat_angle", w.vertical_bat_angle, BatSwing::kVerticalBatAngle, "rad");
  check_range("swing.impact_from_tip", w.impact_from_tip, BatSwing::kImpactFromTip, "m");
  check_range("swing.undercut", w.undercut, BatSwing::kUndercut, "m");
  // The bat narrows both: the contact must be on the barrel beyond the hands (or the ball's
  // edge on the end cap's rim), and the ball centre within reach of the bat's surface there.
  check_range("swing.impact_from_tip (bat '" + bat.name + "': the barrel beyond 5 cm past the pivot, or 95 % of the ball's radius past the tip)",
              w.impact_from_tip, bat_contact_range(bat, ball), "m");
  const double reach_r = bat_ball_reach(bat, ball, w.impact_from_tip);
  check_range("swing.undercut (95 % of bat + ball radius at this contact)", w.undercut,
              Range{-0.95 * reach_r, 0.95 * reach_r, true, true}, "m");
}

void validate_pitch(const Pitch& p) {
  check_range("pitch.speed", p.speed, Pitch::kSpeed, "m/s");
  check_range("pitch.approach_angle", p.approach_angle, Pitch::kApproachAngle, "rad");
  check_range("pitch.spin", p.spin, Pitch::kSpin, "rad/s");
  check_range("pitch.spin_axis", p.spin_axis, Pitch::kSpinAxis, "rad");
}

Delivery deliver_golf(const BallSpec& ball, const ClubSpec& club, const GolfSwing& swing,
                      const ImpactMaterial& material) {
  validate_ball(ball);
  validate_club(club);
  validate_material(material, "impact");
  validate_golf_swing(swing, club);
  const double loft = face_centre_loft(swing, club);
  const double face_angle = face_centre_face_angle(swing, club);

  // Head pose: loft about the head's toe axis (z), then the face angle about vertical
  // (+ open turns the face toward +z, i.e. right).
  const Quat q = axis_angle(-face_angle, Vec3::UnitY()) * axis_angle(loft, Vec3::UnitZ());
  const Mat3 rot = q.toRotationMatrix();

  // Contact point and normal on the curved face, head frame.
  const double toe = swing.impact_toe, up = strike_up(swing, club);
  const Vec3 p_head(-(toe * toe / (2.0 * club.bulge_radius) + up * up / (2.0 * club.roll_radius)), up, toe);
  const Vec3 n_head = Vec3(1.0, up / club.roll_radius, toe / club.bulge_radius).normalized();
  const Vec3 n = (rot * n_head).normalized();

  // The ball sits on the tee at the origin; the face touches it where the normal says.
  const Vec3 ball_centre(0.0, ball.radius, 0.0);
  const Vec3 touch = ball_centre - ball.radius * n;  // first touch, on the face surface
  const Vec3 face_centre = touch - rot * p_head;

  // Head motion: the face centre moves at club_speed along attack angle and path; the
  // closure rate turns the head about the shaft axis (rising from the heel toward the
  // golfer at the lie angle; + about it closes the face for a right-hander).
  const Vec3 v_face = swing.club_speed * head_direction(swing);
  const Vec3 shaft_axis(0.0, std::sin(club.lie), -std::cos(club.lie));
  const Vec3 omega = swing.closure_rate * shaft_axis;

  RigidBody head;
  head.mass = club.head_mass + club.shaft_tip_mass;
  head.inertia_body = club.inertia;
  head.orientation = q;
  head.position = face_centre + rot * club.cg;
  head.velocity = v_face + omega.cross(head.position - face_centre);
  head.angular_velocity = omega;

  RigidBody b;
  b.mass = ball.mass;
  b.inertia_body = Mat3::Identity() * ball.inertia;
  b.position = ball_centre;

  Delivery d;
  d.impact_input.impactor = make_impact_body(head, touch, "club '" + club.name + "'");
  d.impact_input.ball = make_impact_body(b, touch, "ball '" + ball.name + "'");
  d.impact_input.normal = n;
  d.impact_input.material = material;
  if (uses_duration(ball, material)) {
    CompliantImpactInput in;
    in.impactor = head;
    in.surface_origin = -club.cg;  // the face centre seen from the head's CG, head axes
    in.surface.kind = ImpactSurface::Kind::Face;
    in.surface.bulge_radius = club.bulge_radius;
    in.surface.roll_radius = club.roll_radius;
    in.ball = b;
    in.ball_radius = ball.radius;
    in.contact.ball = ball.compliance;
    in.contact.material = material;
    in.contact.cor_factor = club.face_cor_factor(toe, up);
    solve_compliant_into(d, in, "golf delivery");
  } else {
    solve_into(d, "golf delivery");
  }
  record_bodies(d, head, b);

  d.launch = launch_of(d.impact, ball_centre);
  d.impactor_at_impact = ImpactorPose{face_centre, q, v_face, omega};
  d.impactor_speed = head.point_velocity(touch).norm();
  d.smash_factor = d.launch.velocity.norm() / d.impactor_speed;
  return d;
}

Vec3 bat_axis_across(const Vec3& path, const Vec3& level, double vertical_bat_angle) {
  const double cos_climb = std::sqrt(std::max(0.0, 1.0 - path.y() * path.y()));
  const double turn = std::asin(std::clamp(std::sin(vertical_bat_angle) / std::max(cos_climb, 1e-9), -1.0, 1.0));
  return std::cos(turn) * level - std::sin(turn) * path.cross(level);
}

Delivery deliver_baseball(const BallSpec& ball, const BatSpec& bat, const BatSwing& swing, const Pitch& pitch,
                          const ImpactMaterial& material) {
  validate_pitch(pitch);
  // The pitch: from +x toward the plate, descending at the approach angle, spinning with
  // DESIGN §2's decomposition (backspin axis for v̂ = -x is -z).
  const Vec3 ball_centre(0.0, kBaseballContactHeight, 0.0);
  const LaunchState pitched = launch_from_metrics(pitch.speed, -pitch.approach_angle, kPi, pitch.spin,
                                                  pitch.spin_axis, ball_centre);
  return deliver_baseball(ball, bat, swing, pitched.velocity, pitched.spin, material);
}

Delivery deliver_baseball(const BallSpec& ball, const BatSpec& bat, const BatSwing& swing, const Vec3& pitch_velocity,
                          const Vec3& pitch_spin, const ImpactMaterial& material) {
  validate_ball(ball);
  validate_bat(bat);
  validate_material(material, "impact");
  validate_bat_swing(swing, bat, ball);
  if (!pitch_velocity.allFinite() || !pitch_spin.allFinite())
    throw InputError("pitch: velocity and spin must be finite numbers");
  check_range("pitch speed", pitch_velocity.norm(), Pitch::kSpeed, "m/s");
  check_range("pitch spin", pitch_spin.norm(), Pitch::kSpin, "rad/s");
  const double past_tip = std::max(-swing.impact_from_tip, 0.0);  // the ball's centre past the end
  const double from_knob = bat.length - std::max(swing.impact_from_tip, 0.0);
  const double reach_r = bat_ball_reach(bat, ball, swing.impact_from_tip);

  // Swing frame: the bat axis (knob -> tip) points toward +z (first-base side, the batter
  // stands on the third-base side as a right-hander), the sweet spot moves along d (tilted
  // up by the attack angle), and the whole swing is turned by `direction` about vertical.
  // The axis then turns about d, head down by the vertical bat angle: it stays across d.
  const Quat turn = axis_angle(-swing.direction, Vec3::UnitY());
  const double ca = std::cos(swing.attack_angle), sa = std::sin(swing.attack_angle);
  const Vec3 d = turn * Vec3(ca, sa, 0.0);
  const Vec3 level = turn * Vec3::UnitZ();
  const Vec3 axis = bat_axis_across(d, level, swing.vertical_bat_angle);
  const Vec3 up = axis.cross(d);  // ⊥ axis and d, upward for a level swing
  const double sin_b = swing.undercut / reach_r;
  const Vec3 across = (std::sqrt(1.0 - sin_b * sin_b) * d + sin_b * up).normalized();  // from the axis to the ball
  // On the barrel the contact's normal runs straight out from the axis; on the end cap's rim
  // it tilts out along the axis by the ball's overhang.
  const double sin_c = past_tip / ball.radius;
  const Vec3 n = (std::sqrt(1.0 - sin_c * sin_c) * across + sin_c * axis).normalized();

  const Vec3 ball_centre(0.0, kBaseballContactHeight, 0.0);
  const Vec3 on_axis = ball_centre - reach_r * across - past_tip * axis;  // bat axis point under the contact
  const Vec3 knob = on_axis - from_knob * axis;
  const Vec3 contact = ball_centre - ball.radius * n;
  const Vec3 pivot = knob + bat.pivot_from_knob * axis;
  const double sweet_arm = bat.sweet_arm();
  const Vec3 omega = (swing.bat_speed / sweet_arm) * up;  // ω × (arm·axis) = bat_speed·d

  // Bat frame -> world: x along the axis, y = up, z = -d (right-handed).
  Mat3 bat_axes;
  bat_axes.col(0) = axis;
  bat_axes.col(1) = up;
  bat_axes.col(2) = axis.cross(up);
  const Quat q(bat_axes);

  RigidBody batb;
  batb.mass = bat.mass;
  batb.inertia_body = Vec3(bat.inertia_axial, bat.inertia_cg, bat.inertia_cg).asDiagonal();
  batb.orientation = q;
  batb.position = knob + bat.cg_from_knob * axis;
  batb.velocity = omega.cross(batb.position - pivot);
  batb.angular_velocity = omega;

  RigidBody b;
  b.mass = ball.mass;
  b.inertia_body = Mat3::Identity() * ball.inertia;
  b.position = ball_centre;
  b.velocity = pitch_velocity;
  b.angular_velocity = pitch_spin;

  Delivery dl;
  dl.impact_input.impactor = make_impact_body(batb, contact, "bat '" + bat.name + "'");
  dl.impact_input.ball = make_impact_body(b, contact, "ball '" + ball.name + "'");
  dl.impact_input.normal = n;
  // Barrel vibrations: restitution falls away from the node (BatSpec::cor_profile).
  const double factor = bat.cor_factor_at(std::max(swing.impact_from_tip, 0.0));
  if (uses_duration(ball, material)) {
    CompliantImpactInput in;
    in.impactor = batb;
    in.surface_origin = Vec3(-bat.cg_from_knob, 0.0, 0.0);  // the knob seen from the CG, bat axes
    in.surface.kind = ImpactSurface::Kind::Barrel;
    in.surface.bat = &bat;
    in.ball = b;
    in.ball_radius = ball.radius;
    in.contact.ball = ball.compliance;
    in.contact.material = material;
    in.contact.cor_factor = factor;
    dl.impact_input.material = material;
    solve_compliant_into(dl, in, "baseball delivery");
  } else {
    ImpactMaterial m = material;
    for (int i = 0; i < m.e.count; ++i) m.e.cor[static_cast<size_t>(i)] *= factor;
    dl.impact_input.material = m;
    solve_into(dl, "baseball delivery");
  }
  record_bodies(dl, batb, b);

  dl.launch = launch_of(dl.impact, ball_centre);
  dl.impactor_at_impact = ImpactorPose{knob, q, batb.point_velocity(knob), omega};
  dl.impactor_speed = batb.point_velocity(contact).norm();
  dl.smash_factor = dl.launch.velocity.norm() / dl.impactor_speed;
  return dl;
}

bool uses_duration(const BallSpec& ball, const ImpactMaterial& m) {
  return ball.compliance.stiffness > 0.0 && m.model == ImpactModel::Compliant && m.friction != FrictionModel::Textbook;
}

}  // namespace sweetspot
