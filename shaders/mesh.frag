#version 330 core
in vec3 v_rel;
in vec3 v_normal;
in vec2 v_uv;
uniform vec4 u_base_color;
uniform vec3 u_emissive;
uniform bool u_has_base_tex;
uniform bool u_has_emissive_tex;
uniform sampler2D u_base_tex;
uniform sampler2D u_emissive_tex;
uniform vec3 u_tint;
uniform float u_emissive_boost;
uniform vec3 u_flash;
uniform vec3 u_team_color;  // the ship's team colour
uniform float u_team_mask;  // how much of this material takes it (material share × instance strength)
uniform vec3 u_light_dir;   // direction the light travels
uniform vec3 u_light_color;
uniform vec3 u_ambient;
out vec4 o_color;
void main() {
  vec3 n = normalize(v_normal);
  if (!gl_FrontFacing) n = -n;
  vec3 l = -normalize(u_light_dir);
  float rl = length(v_rel);
  vec3 v = rl > 1e-6 ? -v_rel / rl : vec3(0.0, 0.0, 1.0);
  vec3 h = l + v;
  h = dot(h, h) > 1e-12 ? normalize(h) : n;
  vec4 base = u_base_color;
  if (u_has_base_tex) base *= texture(u_base_tex, v_uv);
  vec3 albedo = mix(base.rgb, u_team_color, u_team_mask) * u_tint;
  float ndl = max(dot(n, l), 0.0);
  float spec = ndl > 0.0 ? pow(max(dot(n, h), 0.0), 48.0) * 0.35 : 0.0;
  vec3 emissive = u_emissive;
  if (u_has_emissive_tex) emissive *= texture(u_emissive_tex, v_uv).rgb;
  // A team-coloured glow keeps the material's brightness and takes the team's hue.
  emissive = mix(emissive, u_team_color * max(emissive.r, max(emissive.g, emissive.b)), u_team_mask);
  vec3 c = albedo * (u_ambient + u_light_color * ndl + u_flash) + u_light_color * spec + emissive * u_emissive_boost;
  o_color = vec4(c, 1.0);
}
