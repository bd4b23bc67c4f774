#version 330 core
// Faint nebula: two broad coloured lobes plus low-frequency value noise on the view direction.
// Evaluated per pixel every frame with render.sky = exact; otherwise it renders the six faces of
// the cube map sky.frag samples (u_cam_basis then maps a face's pixels to its directions).
in vec2 v_ndc;
uniform mat3 u_cam_basis;   // columns: camera right, up, back in world space
uniform vec2 u_tan_half;    // tan(fov_x/2), tan(fov_y/2)
uniform vec3 u_lobe_a;      // seeded directions of the nebula lobes
uniform vec3 u_lobe_b;
uniform float u_seed;
uniform bool u_linear;      // HDR: output scene light that tone-maps back to the picked tints
out vec4 o_color;

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
float hash3(vec3 p) { return fract(sin(dot(p, vec3(12.9898, 78.233, 37.719)) + u_seed) * 43758.5453); }
float noise3(vec3 p) {
  vec3 i = floor(p), f = fract(p);
  f = f * f * (3.0 - 2.0 * f);
  float n000 = hash3(i), n100 = hash3(i + vec3(1, 0, 0)), n010 = hash3(i + vec3(0, 1, 0)), n110 = hash3(i + vec3(1, 1, 0));
  float n001 = hash3(i + vec3(0, 0, 1)), n101 = hash3(i + vec3(1, 0, 1)), n011 = hash3(i + vec3(0, 1, 1)), n111 = hash3(i + vec3(1, 1, 1));
  return mix(mix(mix(n000, n100, f.x), mix(n010, n110, f.x), f.y), mix(mix(n001, n101, f.x), mix(n011, n111, f.x), f.y), f.z);
}
void main() {
  vec3 d = normalize(u_cam_basis * vec3(v_ndc * u_tan_half, -1.0));
  float n = 0.55 * noise3(d * 3.0) + 0.3 * noise3(d * 7.0) + 0.15 * noise3(d * 15.0);
  float a = pow(max(dot(d, u_lobe_a) * 0.5 + 0.5, 0.0), 4.0);
  float b = pow(max(dot(d, u_lobe_b) * 0.5 + 0.5, 0.0), 5.0);
  vec3 c = vec3(0.006, 0.007, 0.014);
  c += a * n * n * vec3(0.16, 0.05, 0.20);
  c += b * n * n * vec3(0.03, 0.11, 0.17);
  o_color = vec4(u_linear ? display_to_scene(c) : c, 1.0);
}
