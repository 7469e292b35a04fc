#version 330 core
// Unlit overlay geometry (trail, markers, labels): world position and vertex colour. Ribbons
// (the trail) set a_normal.x = 1 and carry their across-ribbon coordinate (-1..1) in
// a_pattern, so the fragment shader can soften their edges without multisampling. The trail's
// halo sets a_normal.x = 2 and its opacity in a_normal.y.
layout(location = 0) in vec3 a_position;
layout(location = 1) in vec3 a_normal;
layout(location = 2) in vec3 a_color;
layout(location = 3) in float a_pattern;

uniform mat4 u_view_proj;

out vec3 v_color;
out float v_across;
flat out float v_feather;
out float v_opacity;

void main() {
  v_color = a_color;
  v_across = a_pattern;
  v_feather = a_normal.x;
  v_opacity = a_normal.y;
  gl_Position = u_view_proj * vec4(a_position, 1.0);
}
