#version 330 core
// Sun + sky ambient lighting with distance haze. Mown-grass stripes (a_pattern = 1) run
// across the x (downrange) axis every 12 m and fade out where they would alias.
in vec3 v_world;
in vec3 v_normal;
in vec3 v_color;
in float v_pattern;

uniform vec3 u_eye;
uniform vec3 u_sun_dir;      // unit, toward the sun
uniform vec3 u_haze;         // colour of the far distance (the sky at the horizon)
uniform float u_haze_range;  // m, distance at which haze reaches 63 %
uniform float u_specular;    // 0 for terrain (grass has no sun glint), 1 for ball and equipment

out vec4 frag_color;

void main() {
  vec3 to_eye = u_eye - v_world;
  float dist = length(to_eye);
  vec3 v = to_eye / max(dist, 1e-4);
  vec3 n = normalize(v_normal);
  if (dot(n, v) < 0.0) n = -n;  // light the side the camera sees, whatever the winding

  float stripe_coord = v_world.x / 12.0;
  float aa = clamp(1.0 - 2.0 * fwidth(stripe_coord), 0.0, 1.0);
  float stripe = v_pattern * aa * (step(0.5, fract(stripe_coord)) - 0.5) * 0.14;
  vec3 albedo = v_color * (1.0 + stripe);

  float diffuse = max(dot(n, u_sun_dir), 0.0);
  vec3 sky_ambient = mix(vec3(0.35, 0.33, 0.30), vec3(0.55, 0.62, 0.75), 0.5 + 0.5 * n.y);
  vec3 h = normalize(u_sun_dir + v);
  float spec = pow(max(dot(n, h), 0.0), 48.0) * 0.18 * u_specular;
  vec3 lit = albedo * (0.72 * diffuse * vec3(1.0, 0.97, 0.90) + 0.52 * sky_ambient) + spec;

  float haze = 1.0 - exp(-dist / u_haze_range);
  frag_color = vec4(mix(lit, u_haze, haze), 1.0);
}
