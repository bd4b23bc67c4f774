#version 330 core
// Lit opaque surfaces, in linear terms: a directional key light with a physically normalised
// Blinn-Phong highlight (Schlick Fresnel, shininess from the material's roughness), a
// hemisphere ambient with a soft fill opposite the key, a Fresnel rim lit by the surroundings
// so silhouettes read against black space, the flash of a hit, and emissive light.
// Colours come in as linear values; the textures' detail is multiplied in as sampled.
in vec3 v_rel;
in vec3 v_normal;
in vec2 v_uv;
uniform vec4 u_base_color;
uniform vec3 u_emissive;
uniform float u_metallic;
uniform float u_roughness;
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

const float kPi = 3.14159265;

vec3 fresnel_schlick(vec3 f0, float cos_theta) {
  float m = 1.0 - clamp(cos_theta, 0.0, 1.0);
  float m2 = m * m;
  return f0 + (1.0 - f0) * (m2 * m2 * m);
}

void main() {
  vec3 n = normalize(v_normal);
  if (!gl_FrontFacing) n = -n;
  vec3 l = -normalize(u_light_dir);
  float rl = length(v_rel);
  vec3 v = rl > 1e-6 ? -v_rel / rl : vec3(0.0, 0.0, 1.0);
  vec3 h = l + v;
  h = dot(h, h) > 1e-12 ? normalize(h) : n;
  // The detail texture (panel lines) darkens the material's colour, the team's colour as well.
  vec4 detail = u_has_base_tex ? texture(u_base_tex, v_uv) : vec4(1.0);
  vec3 albedo = mix(u_base_color.rgb, u_team_color, u_team_mask) * detail.rgb * u_tint;
  float metal = clamp(u_metallic, 0.0, 1.0);
  float ndl = max(dot(n, l), 0.0);
  float ndv = max(dot(n, v), 0.0);
  // Key light: diffuse (metals keep part of it: these are painted hulls) plus the highlight.
  float r = clamp(u_roughness, 0.08, 1.0);
  float r2 = r * r;
  float shininess = clamp(2.0 / (r2 * r2) - 2.0, 2.0, 1024.0);
  vec3 f0 = mix(vec3(0.04), albedo, metal);
  vec3 spec = fresnel_schlick(f0, dot(v, h)) * ((shininess + 8.0) / (8.0 * kPi)) * pow(max(dot(n, h), 0.0), shininess);
  spec *= ndl * detail.r;  // no highlight in the grooves
  vec3 diffuse = albedo * (1.0 - 0.5 * metal);
  // Ambient from above and a fill from the side away from the key, so the shadowed half of a
  // hull keeps its shape instead of going black.
  float fill = max(-dot(n, l), 0.0);
  vec3 ambient = u_ambient * (1.0 + 0.5 * n.y + 2.5 * fill);
  // Rim: grazing surfaces reflect the surroundings, and a key light behind the hull (toward the
  // eye) catches its outline the most, so a backlit ship is outlined instead of a black cut-out.
  float grazing = 1.0 - ndv;
  float rim = grazing * grazing;
  float behind = max(dot(-v, l), 0.0);
  vec3 rim_light = (u_ambient * 3.0 + u_light_color * (0.05 + 0.6 * behind * behind)) * rim * mix(vec3(1.0), albedo, 0.5);
  vec3 emissive = u_emissive;
  if (u_has_emissive_tex) emissive *= texture(u_emissive_tex, v_uv).rgb;
  // A team-coloured glow keeps the material's brightness and takes the team's hue.
  emissive = mix(emissive, u_team_color * max(emissive.r, max(emissive.g, emissive.b)), u_team_mask);
  vec3 c = diffuse * (ambient + u_light_color * ndl + u_flash) + u_light_color * spec + rim_light * detail.r +
           emissive * u_emissive_boost;
  o_color = vec4(c, 1.0);
}
