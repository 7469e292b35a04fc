#version 330 core
// Sun + sky ambient lighting with distance haze, and procedural surface detail chosen by the
// vertex's surface look (game/render/mesh_import.hpp surface_look): 0 plain, 1 mown grass
// (stripes across x every 12 m, fine blade noise), 2 long grass (patchy), 3 sand (grain and
// ripples), 4 water (sky reflection at grazing angles, sun glints), 5 dirt (clods, grain),
// 6 cloth (a flag: bright from any side, as the cloth glows with the light through it).
// Large patches come per vertex (lit.vert); one fine noise octave per surface fades out
// where it would alias (its cells under ~2 pixels), so far terrain stays calm and cheap.
in vec3 v_world;
in vec3 v_normal;
in vec3 v_color;
in float v_pattern;
in float v_patch;
in vec4 v_light;

uniform vec3 u_eye;
uniform vec3 u_sun_dir;      // unit, toward the sun
uniform vec3 u_haze;         // colour of the far distance (the sky at the horizon)
uniform float u_haze_range;  // m, distance at which haze reaches 63 %
uniform float u_specular;    // 0 for terrain (grass has no sun glint), 1 for ball and equipment
uniform float u_shadows;     // 1: sample the sun's shadow map; 0: no shadows (software rasterisers by default)
uniform sampler2DShadow u_shadow_map;  // depth from the sun, compared in hardware (2x2 filtered)

out vec4 frag_color;

float hash(vec2 p) {
  p = fract(p * vec2(0.1031, 0.1030));
  p += dot(p, p.yx + 33.33);
  return fract((p.x + p.y) * p.x);
}

// Value noise in [-0.5, 0.5] on cells of `scale` m, faded out where a cell covers under
// about two pixels; far away it costs no hash at all (most of a software rasteriser's
// frame is distant turf).
float noise(vec2 xz, float scale) {
  vec2 q = xz / scale;
  float fade = clamp(2.0 - 6.0 * max(fwidth(q.x), fwidth(q.y)), 0.0, 1.0);
  if (fade <= 0.0) return 0.0;
  vec2 i = floor(q), f = fract(q);
  f = f * f * (3.0 - 2.0 * f);
  float n = mix(mix(hash(i), hash(i + vec2(1.0, 0.0)), f.x), mix(hash(i + vec2(0.0, 1.0)), hash(i + vec2(1.0, 1.0)), f.x), f.y);
  return (n - 0.5) * fade;
}

void main() {
  vec3 to_eye = u_eye - v_world;
  float dist = length(to_eye);
  vec3 v = to_eye / max(dist, 1e-4);
  vec3 n = normalize(v_normal);
  if (dot(n, v) < 0.0) n = -n;  // light the side the camera sees, whatever the winding

  int look = int(v_pattern + 0.5);
  vec2 xz = v_world.xz;
  vec3 albedo = v_color;
  float specular = u_specular, shininess = 48.0;
  if (look == 1) {
    float stripe_coord = v_world.x / 12.0;
    float aa = clamp(1.0 - 2.0 * fwidth(stripe_coord), 0.0, 1.0);
    float stripe = aa * (step(0.5, fract(stripe_coord)) - 0.5) * 0.14;
    albedo *= 1.0 + stripe + v_patch * 0.08 + noise(xz, 0.35) * 0.10;
  } else if (look == 2) {
    albedo *= 1.0 + v_patch * 0.24 + noise(xz, 0.5) * 0.18;
  } else if (look == 3) {
    float ripple = sin(xz.x * 2.2 + v_patch * 5.0) * 0.03 * clamp(1.0 - 20.0 * fwidth(xz.x), 0.0, 1.0);
    albedo *= 1.0 + v_patch * 0.08 + noise(xz, 0.08) * 0.10 + ripple;
  } else if (look == 4) {
    // Wind ripples tilt the normal a little; the water mirrors the sky more at grazing angles
    // (Schlick's Fresnel with n = 1.33: 2 % head-on) and glints where the sun reflects.
    vec2 tilt = vec2(noise(xz, 1.2), noise(xz + 17.0, 1.2)) * 0.25;
    n = normalize(n + vec3(tilt.x, 0.0, tilt.y));
    float fresnel = 0.02 + 0.98 * pow(1.0 - max(dot(n, v), 0.0), 5.0);
    albedo = mix(albedo, u_haze * 1.1, clamp(fresnel, 0.0, 0.8));
    specular = 1.6;
    shininess = 180.0;
  } else if (look == 5) {
    albedo *= 1.0 + v_patch * 0.12 + noise(xz, 0.15) * 0.18;
  }

  float diffuse = max(dot(n, u_sun_dir), 0.0);
  float sunlit = 1.0;
  if (u_shadows > 0.5) {
    vec3 p = v_light.xyz / v_light.w * 0.5 + 0.5;
    if (all(greaterThan(p, vec3(0.0))) && all(lessThan(p, vec3(1.0)))) sunlit = texture(u_shadow_map, p);
  }
  diffuse *= sunlit;
  vec3 sky_ambient = mix(vec3(0.35, 0.33, 0.30), vec3(0.55, 0.62, 0.75), 0.5 + 0.5 * n.y);
  vec3 h = normalize(u_sun_dir + v);
  float spec = pow(max(dot(n, h), 0.0), shininess) * 0.18 * specular * sunlit;
  vec3 lit = albedo * (0.72 * diffuse * vec3(1.0, 0.97, 0.90) + 0.52 * sky_ambient) + spec;
  // A flag's thin cloth glows with the light through it and off both faces: under a high
  // sun a hanging flag gets almost none of it straight on, yet reads bright red from any
  // side and any distance, as the HUD's far flag is drawn.
  if (look == 6) lit = albedo * (0.8 + 0.2 * diffuse);

  float haze = 1.0 - exp(-dist / u_haze_range);
  frag_color = vec4(mix(lit, u_haze, haze), 1.0);
}
