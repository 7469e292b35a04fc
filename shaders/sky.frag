#version 330 core
// Sky gradient by the elevation of the view ray: haze at the horizon to deep blue at the
// zenith, with a soft glow around the sun.
in vec2 v_ndc;

uniform mat4 u_inv_view_proj;
uniform vec3 u_eye;
uniform vec3 u_sun_dir;
uniform vec3 u_horizon;
uniform vec3 u_zenith;

out vec4 frag_color;

void main() {
  vec4 far_point = u_inv_view_proj * vec4(v_ndc, 1.0, 1.0);
  vec3 dir = normalize(far_point.xyz / far_point.w - u_eye);
  float e = clamp(dir.y, 0.0, 1.0);
  vec3 sky = mix(u_horizon, u_zenith, pow(e, 0.55));
  float sun = pow(max(dot(dir, u_sun_dir), 0.0), 64.0);
  frag_color = vec4(sky + sun * vec3(0.35, 0.30, 0.20), 1.0);
}
