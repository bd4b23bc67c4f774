#version 330 core
// The corners of the sky grid's cells as texels (gfx/sky_pass.h): texel (i, j) holds the baked
// nebula in the direction of the corner at NDC −1 + (i, j)·cell size. The last row and column
// lie past the screen's edge where a cell is cut short, so a cut cell is interpolated as a
// whole one would be. Drawn as a full-screen triangle over a texture of one texel per corner.
uniform vec2 u_cell_ndc;    // a cell's size in normalised device coordinates
uniform mat3 u_cam_basis;   // columns: camera right, up, back in world space
uniform vec2 u_tan_half;    // tan(fov_x/2), tan(fov_y/2)
uniform samplerCube u_sky;
uniform float u_edge_scale; // (n − 1)/n, as sky.frag
out vec4 o_color;

void main() {
  vec2 ndc = vec2(-1.0) + floor(gl_FragCoord.xy) * u_cell_ndc;
  vec3 d = u_cam_basis * vec3(ndc * u_tan_half, -1.0);
  vec3 a = abs(d);
  float major = max(a.x, max(a.y, a.z));
  d *= mix(vec3(u_edge_scale), vec3(1.0), vec3(greaterThanEqual(a, vec3(major))));
  o_color = vec4(textureLod(u_sky, d, 0.0).rgb, 1.0);
}
