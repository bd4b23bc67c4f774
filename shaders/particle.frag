#version 330 core
// Controlled-additive blending (Ilmonen 2006 §4): with premultiplied sprite tcola and colour
// fgc = rgb·alpha the output is (fgc·tcola, alpha·talpha·(1 − burn)) under
// glBlendFunc(GL_ONE, GL_ONE_MINUS_SRC_ALPHA). Soft edges scale both (§3, Lorach, Krazanowski).
in vec3 v_uv;
in vec4 v_color;
in float v_burn;
in float v_depth;
in float v_extent;
flat in uint v_soft;
uniform sampler2DArray u_sprites;
uniform sampler2D u_scene_depth;  // this frame's opaque depth, copied
uniform bool u_soft_enabled;
uniform vec2 u_linearize;         // view depth = x / (depth + y) for the depth mode in use
uniform float u_contrast_power;
uniform float u_near;
uniform float u_near_fade;
out vec4 o_color;

const float kEps = 1e-6;

float contrast(float x, float p) {
  return x < 0.5 ? 0.5 * pow(2.0 * x, p) : 1.0 - 0.5 * pow(2.0 * (1.0 - x), p);
}

void main() {
  vec4 tex = texture(u_sprites, v_uv);
  float k = 1.0;
  if (u_soft_enabled && v_soft != 0u) {
    float d = texelFetch(u_scene_depth, ivec2(gl_FragCoord.xy), 0).r;
    float denom = d + u_linearize.y;
    float zb = abs(denom) > 1e-30 ? u_linearize.x / denom : 1e30;
    float diff = zb - v_depth;
    if (v_soft == 1u) {
      k = clamp(diff / v_extent, 0.0, 1.0);
    } else if (v_soft == 2u) {
      k = contrast(clamp(diff / v_extent, 0.0, 1.0), u_contrast_power);
    } else if (v_soft == 3u) {
      // Average density: the fraction of the volume [z − E/2, z + E/2] in front of the scene;
      // the quad already sits at z − E/2.
      k = clamp(diff / v_extent, 0.0, 1.0);
    } else {
      // Density extent: texture alpha is the volume's extent around the mirror plane.
      // The quad sits at z − E, so the mirror plane is one extent behind it.
      float range = (diff - v_extent) / v_extent / max(tex.a, kEps);
      k = clamp(range, -1.0, 1.0) * 0.5 + 0.5;
    }
  }
  if (u_near_fade > 0.0) k *= clamp((v_depth - u_near) / u_near_fade, 0.0, 1.0);
  o_color = vec4(v_color.rgb * tex.rgb, v_color.a * tex.a * (1.0 - v_burn)) * k;
}
