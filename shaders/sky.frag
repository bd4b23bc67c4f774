#version 330 core
// The nebula baked into a cube map (sky_exact.frag renders each face once per level seed and
// resolution): one filtered lookup per pixel instead of three octaves of value noise.
in vec2 v_ndc;
uniform mat3 u_cam_basis;   // columns: camera right, up, back in world space
uniform vec2 u_tan_half;    // tan(fov_x/2), tan(fov_y/2)
uniform samplerCube u_sky;
out vec4 o_color;

void main() {
  vec3 d = u_cam_basis * vec3(v_ndc * u_tan_half, -1.0);
  o_color = vec4(texture(u_sky, d).rgb, 1.0);
}
