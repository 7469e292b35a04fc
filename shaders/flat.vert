#version 330 core
// Unlit overlay geometry (trail, markers, labels): world position and vertex colour. Ribbons
// (the trail) set a_normal.x = 1 and carry their across-ribbon coordinate (-1..1) in
// a_pattern, so the fragment shader can soften their edges without multisampling.
layout(location = 0) in vec3 a_position;
layout(location = 1) in vec3 a_normal;
layout(location = 2) in vec3 a_color;
layout(location = 3) in float a_pattern;

uniform mat4 u_view_proj;

out vec3 v_color;
out float v_across;
flat out float v_feather;

void main() {
  v_color = a_color;
  v_across = a_pattern;
  v_feather = a_normal.x;
  gl_Position = u_view_proj * vec4(a_position, 1.0);
}
