#version 330 core
// Lit meshes (terrain, ball, club, bat, flag): world-space position and normal to the
// fragment shader; colour and surface look come per vertex from the material palette, and a
// random per vertex gives the terrain its large patches for free.
layout(location = 0) in vec3 a_position;
layout(location = 1) in vec3 a_normal;
layout(location = 2) in vec3 a_color;
layout(location = 3) in float a_pattern;

uniform mat4 u_model;
uniform mat3 u_normal_matrix;
uniform mat4 u_view_proj;
uniform mat4 u_light_view_proj;  // world -> the sun's shadow map (clip)

out vec3 v_world;
out vec3 v_normal;
out vec3 v_color;
out float v_pattern;
out float v_patch;
out vec4 v_light;  // this point in the shadow map's clip space  // -0.5..0.5: per-vertex random, interpolated: turf and dirt patches at the mesh's cell size

float hash(vec2 p) {
  p = fract(p * vec2(0.1031, 0.1030));
  p += dot(p, p.yx + 33.33);
  return fract((p.x + p.y) * p.x);
}

void main() {
  vec4 world = u_model * vec4(a_position, 1.0);
  v_world = world.xyz;
  v_normal = u_normal_matrix * a_normal;
  v_color = a_color;
  v_pattern = a_pattern;
  v_patch = hash(floor(world.xz * 4.0)) - 0.5;
  v_light = u_light_view_proj * world;
  gl_Position = u_view_proj * world;
}
