#version 330 core
// The nebula baked into a cube map (sky_exact.frag renders each face once per level seed and
// resolution): one filtered lookup per pixel instead of three octaves of value noise.
in vec2 v_ndc;
uniform mat3 u_cam_basis;   // columns: camera right, up, back in world space
uniform vec2 u_tan_half;    // tan(fov_x/2), tan(fov_y/2)
uniform samplerCube u_sky;
uniform float u_edge_scale;  // (n − 1)/n: the faces are baked with texel centres on their edges
out vec4 o_color;

void main() {
  vec3 d = u_cam_basis * vec3(v_ndc * u_tan_half, -1.0);
  // The major axis picks the face and stays; the two minor coordinates shrink so that the
  // face's [−1, 1] reaches exactly its edge texels' centres (sky_pass.cpp, bake).
  vec3 a = abs(d);
  float major = max(a.x, max(a.y, a.z));
  d *= mix(vec3(u_edge_scale), vec3(1.0), vec3(greaterThanEqual(a, vec3(major))));
  o_color = vec4(texture(u_sky, d).rgb, 1.0);
}
