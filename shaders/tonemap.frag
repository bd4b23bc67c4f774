#version 330 core
// The HDR resolve: linear scene (+ bloom) × exposure through a filmic curve, written as sRGB.
// The curve is Narkowicz's fit of the ACES reference rendering and output transforms
// ("ACES Filmic Tone Mapping Curve", 2016): x(2.51x + 0.03) / (x(2.43x + 0.59) + 0.14), per
// channel, so bright light desaturates toward white the way film does (a white-hot core with an
// orange fringe) instead of clipping each channel at 1.
in vec2 v_uv;
uniform sampler2D u_scene;
uniform sampler2D u_bloom;
uniform float u_exposure;
uniform float u_bloom_strength;  // bloom chain sum × strength / levels, added in linear light
out vec4 o_color;

vec3 aces_fit(vec3 x) { return clamp(x * (2.51 * x + 0.03) / (x * (2.43 * x + 0.59) + 0.14), 0.0, 1.0); }

vec3 linear_to_srgb(vec3 c) {
  vec3 lo = c * 12.92, hi = 1.055 * pow(c, vec3(1.0 / 2.4)) - 0.055;
  return mix(hi, lo, vec3(lessThanEqual(c, vec3(0.0031308))));
}

void main() {
  vec3 c = textureLod(u_scene, v_uv, 0.0).rgb;
#if BLOOM
  c += textureLod(u_bloom, v_uv, 0.0).rgb * u_bloom_strength;
#endif
  o_color = vec4(linear_to_srgb(aces_fit(max(c, vec3(0.0)) * u_exposure)), 1.0);
}
