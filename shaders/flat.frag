#version 330 core
// The overlay colour unchanged, so a trail pixel is exactly its phase colour; ribbon edges
// fade over about one pixel (analytic anti-aliasing, cheap on a software rasteriser); the
// trail's halo fades from its centre line out.
in vec3 v_color;
in float v_across;
flat in float v_feather;
in float v_opacity;
out vec4 frag_color;

void main() {
  float alpha = 1.0;
  if (v_feather > 1.5) {
    // Halo: strongest on the centre line, gone at its edges (a soft glow, not a band).
    float edge = 1.0 - abs(v_across);
    alpha = v_opacity * edge * edge;
  } else if (v_feather > 0.5) {
    float edge = 1.0 - abs(v_across);           // 0 at the ribbon edge, 1 at its centre
    alpha = clamp(edge / max(fwidth(v_across), 1e-6), 0.0, 1.0);
  }
  frag_color = vec4(v_color, alpha);
}
