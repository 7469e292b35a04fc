#version 330 core
// Unlit overlay geometry (trail, markers, labels): world position and vertex colour only.
layout(location = 0) in vec3 a_position;
layout(location = 2) in vec3 a_color;

uniform mat4 u_view_proj;

out vec3 v_color;

void main() {
  v_color = a_color;
  gl_Position = u_view_proj * vec4(a_position, 1.0);
}
