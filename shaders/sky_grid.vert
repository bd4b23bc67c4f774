#version 330 core
// The baked nebula on a screen-space grid (render.sky_grid pixels a cell): the cube map is
// looked up at the grid's corners and the colour interpolated across each cell, so a pixel
// costs an interpolation instead of a cube-map sample. Two triangles a cell, made from
// gl_VertexID; the last row and column are cut at the screen's edge.
uniform int u_cells_x;      // cells across
uniform vec2 u_cell_ndc;    // a cell's size in normalised device coordinates
uniform mat3 u_cam_basis;   // columns: camera right, up, back in world space
uniform vec2 u_tan_half;    // tan(fov_x/2), tan(fov_y/2)
uniform samplerCube u_sky;
uniform float u_edge_scale; // (n − 1)/n, as sky.frag
out vec3 v_color;

void main() {
  int cell = gl_VertexID / 6, corner = gl_VertexID % 6;
  ivec2 k = ivec2(corner == 1 || corner == 4 || corner == 5 ? 1 : 0, corner == 2 || corner == 3 || corner == 5 ? 1 : 0);
  vec2 ndc = min(vec2(-1.0) + vec2(ivec2(cell % u_cells_x, cell / u_cells_x) + k) * u_cell_ndc, vec2(1.0));
  vec3 d = u_cam_basis * vec3(ndc * u_tan_half, -1.0);
  vec3 a = abs(d);
  float major = max(a.x, max(a.y, a.z));
  d *= mix(vec3(u_edge_scale), vec3(1.0), vec3(greaterThanEqual(a, vec3(major))));
  v_color = textureLod(u_sky, d, 0.0).rgb;
  gl_Position = vec4(ndc, 0.0, 1.0);
}
