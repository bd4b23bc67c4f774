#version 330 core
// The nebula interpolated between the grid's corners (sky_cells.vert): a texture read and
// nothing else, which llvmpipe draws with its linear rasteriser into an 8-bit BGRA target
// without depth (gfx/sky_pass.h). The corners' alpha is 1.
in vec2 v_uv;
uniform sampler2D u_corners;
out vec4 o_color;
void main() { o_color = texture(u_corners, v_uv); }
