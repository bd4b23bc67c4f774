#version 330 core
// Stars are directions (w = 0), so they sit at infinity whatever the depth mode.
layout(location = 0) in vec4 a_dir_size;  // unit direction, point size in pixels
layout(location = 1) in vec3 a_color;
uniform mat4 u_view_proj;  // rotation-only view, times projection
uniform float u_pixel_scale;
uniform bool u_linear;      // HDR: the colours were picked as sRGB; decode them to linear light
out vec3 v_color;
vec3 srgb_to_linear(vec3 c) {
  vec3 lo = c / 12.92, hi = pow((c + 0.055) / 1.055, vec3(2.4));
  return mix(hi, lo, vec3(lessThanEqual(c, vec3(0.04045))));
}
void main() {
  gl_Position = u_view_proj * vec4(a_dir_size.xyz, 0.0);
  gl_Position.z = 0.0;
  gl_PointSize = max(a_dir_size.w * u_pixel_scale, 1.0);
  v_color = u_linear ? srgb_to_linear(a_color) : a_color;
}
