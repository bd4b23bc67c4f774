#version 330 core
// The screen as one rectangle, two triangles from gl_VertexID, whose uv puts each pixel at its
// place among the grid's corners in the corner texture (sky_corners.frag): pixel x lies x/N
// cells from the left edge, at texel x/N + 1/2. Bilinear filtering then interpolates the nebula
// across every N-pixel cell.
uniform vec2 u_corner_scale;  // scene pixels / (N · corner texels): uv per half NDC unit
uniform vec2 u_corner_offset; // 1/2 texel in uv
out vec2 v_uv;

void main() {
  int corner = gl_VertexID % 6;
  vec2 k = vec2(corner == 1 || corner == 4 || corner == 5 ? 1.0 : 0.0, corner == 2 || corner == 3 || corner == 5 ? 1.0 : 0.0);
  v_uv = k * u_corner_scale + u_corner_offset;
  gl_Position = vec4(2.0 * k - 1.0, 0.0, 1.0);
}
