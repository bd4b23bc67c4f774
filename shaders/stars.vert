#version 330 core
// Stars are directions (w = 0), so they sit at infinity whatever the depth mode.
layout(location = 0) in vec4 a_dir_size;  // unit direction, point size in pixels
layout(location = 1) in vec3 a_color;
uniform mat4 u_view_proj;  // rotation-only view, times projection
uniform float u_pixel_scale;
out vec3 v_color;
void main() {
  gl_Position = u_view_proj * vec4(a_dir_size.xyz, 0.0);
  gl_Position.z = 0.0;
  gl_PointSize = max(a_dir_size.w * u_pixel_scale, 1.0);
  v_color = a_color;
}
