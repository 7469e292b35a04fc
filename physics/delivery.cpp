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

#include <cmath>
#include <sstream>
#include <string>

#include "physics/body.hpp"
#include "physics/error.hpp"

namespace sweetspot {

namespace {

constexpr double kDeg = 180.0 / kPi;

void check(const char* field, double v, double lo, double hi, const char* range, double scale = 1.0,
           const char* unit = "") {
  if (!(v >= lo && v <= hi)) {
    std::ostringstream os;
    os << field << " must be " << range << ", got " << v * scale << unit;
    throw InputError(os.str());
  }
}

Quat axis_angle(double angle, const Vec3& axis) { return Quat(Eigen::AngleAxisd(angle, axis)); }

LaunchState launch_of(const ImpactResult& r, const Vec3& ball_centre) {
  LaunchState l;
  l.position = ball_centre;
  l.velocity = r.ball_after.velocity;
  l.spin = r.ball_after.angular_velocity;
  return l;
}

void solve_into(Delivery& d, const char* who) {
  // Far off-centre contact with a slow swing can leave the striking surface moving along or
  // away from the contact normal: a geometric miss, which deserves words a player understands.
  const double closing = -contact_velocity(d.impact_input.impactor, d.impact_input.ball).dot(d.impact_input.normal);
  if (closing <= 0.0) {
    std::ostringstream os;
    os << who << ": the strike misses: at this contact point the " << (std::string(who).starts_with("golf") ? "club" : "bat")
       << " does not close on the ball (closing speed " << closing
       << " m/s along the contact normal); hit nearer the centre or swing faster";
    throw InputError(os.str());
  }
  if (auto msg = validate_impact(d.impact_input); !msg.empty()) {
    throw InputError(std::string(who) + ": " + msg);
  }
  d.impact = solve_impact(d.impact_input);
}

}  // namespace

Delivery deliver_golf(const BallSpec& ball, const ClubSpec& club, const GolfSwing& swing,
                      const ImpactMaterial& material) {
  validate_ball(ball);
  validate_club(club);
  validate_material(material, "impact");
  const double loft = std::isnan(swing.dynamic_loft) ? club.dynamic_loft : swing.dynamic_loft;
  check("swing.speed", swing.club_speed, 1.0, 90.0, "in [1, 90] m/s (2–200 mph)");
  check("swing.attack_angle", swing.attack_angle, deg_to_rad(-30), deg_to_rad(30), "in [-30, 30] deg", kDeg, " deg");
  check("swing.club_path", swing.club_path, deg_to_rad(-30), deg_to_rad(30), "in [-30, 30] deg", kDeg, " deg");
  check("swing.dynamic_loft", loft, deg_to_rad(0), deg_to_rad(75), "in [0, 75] deg", kDeg, " deg");
  check("swing.face_angle", swing.face_angle, deg_to_rad(-30), deg_to_rad(30), "in [-30, 30] deg", kDeg, " deg");
  check("swing.impact_offset toe", swing.impact_toe, -0.05, 0.05, "in [-50, 50] mm", 1000.0, " mm");
  check("swing.impact_offset up", swing.impact_up, -0.03, 0.03, "in [-30, 30] mm", 1000.0, " mm");
  check("swing.closure_rate", swing.closure_rate, -110.0, 110.0, "in [-110, 110] rad/s (±6300 deg/s)", 1.0, " rad/s");

  // Head pose: loft about the head's toe axis (z), then the face angle about vertical
  // (+ open turns the face toward +z, i.e. right).
  const Quat q = axis_angle(-swing.face_angle, Vec3::UnitY()) * axis_angle(loft, Vec3::UnitZ());
  const Mat3 rot = q.toRotationMatrix();

  // Contact point and normal on the curved face, head frame.
  const double toe = swing.impact_toe, up = swing.impact_up;
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
  const double ca = std::cos(swing.attack_angle);
  const Vec3 v_face = swing.club_speed * Vec3(ca * std::cos(swing.club_path), std::sin(swing.attack_angle),
                                              ca * std::sin(swing.club_path));
  const Vec3 shaft_axis(0.0, std::sin(club.lie), -std::cos(club.lie));
  const Vec3 omega = swing.closure_rate * shaft_axis;

  RigidBody head;
  head.mass = club.head_mass;
  head.inertia_body = club.inertia;
  head.orientation = q;
  head.position = face_centre + rot * club.cg;
  head.velocity = v_face + omega.cross(head.position - face_centre);
  head.angular_velocity = omega;

  RigidBody b;
  b.mass = ball.mass;
  b.inertia_body = Mat3::Identity() * ball.inertia;
  b.position = ball_centre;

  // The deformed ball's pressure centre runs ahead of the touch point by contact_offset in
  // the direction the ball slides across the face (BallSpec::contact_offset). Both bodies
  // take the impulse there, so momentum stays exactly conserved. The ball deforms that way
  // because the face drags its surface: with no traction (µ = 0, or the frictionless
  // teaching model) there is no drag, the contact stays a rigid point, and a frictionless
  // strike leaves the ball without spin, as the textbook has it.
  Vec3 contact = touch;
  const Vec3 slide = -head.point_velocity(touch);  // ball at rest: u = -v_head(P)
  const Vec3 slide_t = slide - slide.dot(n) * n;
  const bool traction = material.friction != FrictionModel::None && material.mu > 0.0;
  if (traction && slide_t.norm() > 1e-9 * slide.norm()) contact += ball.contact_offset * slide_t.normalized();

  Delivery d;
  d.impact_input.impactor = make_impact_body(head, contact, "club '" + club.name + "'");
  d.impact_input.ball = make_impact_body(b, contact, "ball '" + ball.name + "'");
  d.impact_input.normal = n;
  d.impact_input.material = material;
  solve_into(d, "golf delivery");

  d.launch = launch_of(d.impact, ball_centre);
  d.impactor_at_impact = ImpactorPose{face_centre, q, v_face, omega};
  d.impactor_speed = head.point_velocity(touch).norm();
  d.smash_factor = d.launch.velocity.norm() / d.impactor_speed;
  return d;
}

Delivery deliver_baseball(const BallSpec& ball, const BatSpec& bat, const BatSwing& swing, const Pitch& pitch,
                          const ImpactMaterial& material) {
  validate_ball(ball);
  validate_bat(bat);
  validate_material(material, "impact");
  check("swing.speed", swing.bat_speed, 1.0, 60.0, "in [1, 60] m/s (2–134 mph)");
  check("swing.attack_angle", swing.attack_angle, deg_to_rad(-45), deg_to_rad(60), "in [-45, 60] deg", kDeg, " deg");
  check("swing.direction", swing.direction, deg_to_rad(-90), deg_to_rad(90), "in [-90, 90] deg", kDeg, " deg");
  const double reach = bat.length - bat.pivot_from_knob - 0.05;
  if (!(swing.impact_from_tip >= 0.0 && swing.impact_from_tip <= reach)) {
    std::ostringstream os;
    os << "swing.impact_from_tip must be in [0, " << reach * 1000 << "] mm (the barrel beyond 5 cm past the pivot), got "
       << swing.impact_from_tip * 1000 << " mm";
    throw InputError(os.str());
  }
  const double from_knob = bat.length - swing.impact_from_tip;
  const double r_bat = bat.radius_at(from_knob);
  const double reach_r = r_bat + ball.radius;
  if (!(std::abs(swing.undercut) < 0.95 * reach_r)) {
    std::ostringstream os;
    os << "swing.undercut must be within ±" << 0.95 * reach_r * 1000 << " mm (95 % of bat + ball radius here), got "
       << swing.undercut * 1000 << " mm";
    throw InputError(os.str());
  }
  check("pitch.speed", pitch.speed, 0.0, 70.0, "in [0, 70] m/s (0–157 mph)");
  check("pitch.approach_angle", pitch.approach_angle, deg_to_rad(-20), deg_to_rad(45), "in [-20, 45] deg", kDeg,
        " deg");
  check("pitch.spin", pitch.spin, 0.0, 500.0, "in [0, 500] rad/s (0–4775 rpm)", 1.0, " rad/s");
  check("pitch.spin_axis", pitch.spin_axis, -kPi, kPi, "in [-180, 180] deg", kDeg, " deg");

  // Swing frame: the bat axis (knob -> tip) points toward +z (first-base side, the batter
  // stands on the third-base side as a right-hander), the sweet spot moves along d (tilted
  // up by the attack angle), and the whole swing is turned by `direction` about vertical.
  const Quat turn = axis_angle(-swing.direction, Vec3::UnitY());
  const double ca = std::cos(swing.attack_angle), sa = std::sin(swing.attack_angle);
  const Vec3 axis = turn * Vec3::UnitZ();
  const Vec3 d = turn * Vec3(ca, sa, 0.0);
  const Vec3 up = axis.cross(d);  // ⊥ axis and d, upward for a level swing
  const double sin_b = swing.undercut / reach_r;
  const Vec3 n = (std::sqrt(1.0 - sin_b * sin_b) * d + sin_b * up).normalized();

  const Vec3 ball_centre(0.0, kBaseballContactHeight, 0.0);
  const Vec3 on_axis = ball_centre - reach_r * n;  // bat axis point under the contact
  const Vec3 knob = on_axis - from_knob * axis;
  const Vec3 contact = ball_centre - ball.radius * n;
  const Vec3 pivot = knob + bat.pivot_from_knob * axis;
  const double sweet_arm = bat.length - bat.sweet_spot_from_tip - bat.pivot_from_knob;
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

  // The pitch: from +x toward the plate, descending at the approach angle, spinning with
  // DESIGN §2's decomposition (backspin axis for v̂ = -x is -z).
  const LaunchState pitched = launch_from_metrics(pitch.speed, -pitch.approach_angle, kPi, pitch.spin,
                                                  pitch.spin_axis, ball_centre);
  RigidBody b;
  b.mass = ball.mass;
  b.inertia_body = Mat3::Identity() * ball.inertia;
  b.position = ball_centre;
  b.velocity = pitched.velocity;
  b.angular_velocity = pitched.spin;

  // Barrel vibrations: restitution falls away from the node (BatSpec::cor_profile).
  ImpactMaterial m = material;
  const double factor = bat.cor_factor_at(swing.impact_from_tip);
  for (int i = 0; i < m.e.count; ++i) m.e.cor[static_cast<size_t>(i)] *= factor;

  Delivery dl;
  dl.impact_input.impactor = make_impact_body(batb, contact, "bat '" + bat.name + "'");
  dl.impact_input.ball = make_impact_body(b, contact, "ball '" + ball.name + "'");
  dl.impact_input.normal = n;
  dl.impact_input.material = m;
  solve_into(dl, "baseball delivery");

  dl.launch = launch_of(dl.impact, ball_centre);
  dl.impactor_at_impact = ImpactorPose{knob, q, batb.point_velocity(knob), omega};
  dl.impactor_speed = batb.point_velocity(contact).norm();
  dl.smash_factor = dl.launch.velocity.norm() / dl.impactor_speed;
  return dl;
}

}  // namespace sweetspot
