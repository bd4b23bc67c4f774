#version 330 core
// Stars are directions (w = 0), so they sit at infinity whatever the depth mode.
layout(location = 0) in vec4 a_dir_size;  // unit direction, point size in pixels
layout(location = 1) in vec3 a_color;
uniform mat4 u_view_proj;  // rotation-only view, times projection
uniform float u_pixel_scale;
uniform bool u_linear;      // HDR: scene light that tone-maps back to the picked colours
out vec3 v_color;
vec3 srgb_to_linear(vec3 c) {
  vec3 lo = c / 12.92, hi = pow((c + 0.055) / 1.055, vec3(2.4));
  return mix(hi, lo, vec3(lessThanEqual(c, vec3(0.04045))));
}
// The backdrop keeps the look it was picked with: a display colour is decoded and taken back
// through the tone map's ACES fit (tonemap.frag), so at exposure 1 it comes out as it went in,
// instead of the curve's toe swallowing the faint nebula.
vec3 display_to_scene(vec3 display) {
  vec3 y = min(srgb_to_linear(display), vec3(0.99));
  vec3 a = 2.51 - 2.43 * y, b = 0.03 - 0.59 * y;
  return (-b + sqrt(b * b + 4.0 * a * 0.14 * y)) / (2.0 * a);
}
void main() {
  gl_Position = u_view_proj * vec4(a_dir_size.xyz, 0.0);
  gl_Position.z = 0.0;
  gl_PointSize = max(a_dir_size.w * u_pixel_scale, 1.0);
  v_color = u_linear ? display_to_scene(a_color) : a_color;
}
