#version 330 core
// The composite's rectangles (gfx/particle_coverage.h): the scene tiles particles can touch,
// in normalised device coordinates; v_uv spans [0, 1] over the whole screen as post.vert's.
layout(location = 0) in vec2 a_ndc;
out vec2 v_uv;
void main() {
  v_uv = a_ndc * 0.5 + 0.5;
  gl_Position = vec4(a_ndc, 0.0, 1.0);
}
