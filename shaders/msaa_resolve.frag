#version 330 core
// MSAA resolve of the linear HDR scene, weighted so the average is taken as if tone-mapped:
// each sample counts 1 / (1 + its brightest channel), and the weighted mean is taken (Karis,
// "Tone mapping", 2013). A plain average of linear samples lets a hull brighter than white
// win the whole pixel after the tone curve, and the edge steps again.
uniform sampler2DMS u_scene_ms;
uniform int u_samples;
out vec4 o_color;

void main() {
  ivec2 p = ivec2(gl_FragCoord.xy);
  vec3 sum = vec3(0.0);
  float weights = 0.0;
  for (int i = 0; i < u_samples; ++i) {
    vec3 c = texelFetch(u_scene_ms, p, i).rgb;
    float w = 1.0 / (1.0 + max(c.r, max(c.g, c.b)));
    sum += c * w;
    weights += w;
  }
  o_color = vec4(sum / weights, 1.0);
}
