#version 330 core
// Vertex pulling: four vertices per ParticleInstance (particles/render_output.h), fetched from
// the frame's particle buffer as a buffer texture (four RGBA32UI texels each); gl_VertexID / 4
// picks the particle and gl_VertexID % 4 the quad corner, two triangles through a static index
// buffer. All vectors are camera-relative, built in view space so the quad always faces the
// camera and the degenerate cases stay finite.
uniform usamplerBuffer u_particles;
// INDEXED (the per-cluster preparation's programs, gfx/particle_batch.h): quad i draws particle
// u_order[i] & 0x7FFFFFFF of the view's particles as uploaded, bit 31 set when no opaque mesh
// reaches its stretch, and the soft-edge override is applied here. Otherwise quad i draws
// particle i as the CPU patched it, and a software rasteriser runs no fetch or branch for it.
#ifndef INDEXED
#define INDEXED 0
#endif
#if INDEXED
uniform usamplerBuffer u_order;
uniform int u_soft_override;  // −1: none
#endif
uniform mat4 u_view;        // rotation only
uniform mat4 u_proj;
uniform float u_tan_half_y; // tan(fov_y / 2)
uniform float u_size_clamp; // largest on-screen size as a fraction of screen height
uniform float u_near;
uniform vec3 u_linearize;   // view depth = x / (y·depth + z), denominator ≥ 0 in every depth mode
uniform bool u_linear;        // HDR: decode the sRGB-picked colour to linear light
// Trimming (gfx/sprite_trim.h): the quad is cut to the box outside which the sprite samples
// zero at the coarsest mip level any of its pixels can read.
uniform sampler2D u_trim;     // texel (level, sprite): the box (u0, v0, u1, v1)
uniform float u_lod_scale;    // sprite texels per pixel at unit view depth and unit half-size
uniform int u_trim_mode;      // 0: level 0 only (no mipmaps), 1: nearest level, 2: trilinear; −1: whole quads
out vec2 v_uv;
out float v_depth;          // linear view depth of this fragment (varies along axis-locked quads)
// Everything constant over one particle is flat, so a software rasteriser interpolates only the
// three values that really vary across the quad (uv, depth).
flat out vec4 v_color;      // (rgb·alpha, alpha·(1 − burn)): burn folded in per instance
// Soft-edge factor k = clamp(x/(y·d + z)·inv_extent·… − (depth·inv_extent + offset·inv_extent − bias)),
// then optionally divided by the texture alpha (density extent) and bent by the contrast curve:
// one formula, no per-method branches, because a software rasteriser pays for every branch on
// every pixel. The per-instance products are taken here, once per vertex.
flat out vec4 v_soft;        // linearize.x·inv_extent, inv_extent, offset·inv_extent − bias, use texture alpha (0/1)
flat out vec2 v_aux;         // contrast (0/1), sprite layer
const float kEps = 1e-6;

vec3 srgb_to_linear(vec3 c) {
  vec3 lo = c / 12.92, hi = pow((c + 0.055) / 1.055, vec3(2.4));
  return mix(hi, lo, vec3(lessThanEqual(c, vec3(0.04045))));
}

// The instance colour is rgb·alpha of an sRGB-picked rgb; in linear light it is
// linear(rgb)·alpha, so the decode goes through the straight colour (eq. 5 unchanged after it).
// A zero alpha with colour (pure light) is decoded as it stands.
vec3 instance_rgb(vec4 c) {
  if (!u_linear) return c.rgb;
  float a = c.a > kEps ? c.a : 1.0;
  return srgb_to_linear(max(c.rgb / a, vec3(0.0))) * a;
}

void main() {
  int quad = gl_VertexID >> 2;
#if INDEXED
  uint entry = texelFetch(u_order, quad).r;
  int first = int(entry & 0x7FFFFFFFu) * 4;
#else
  int first = quad * 4;
#endif
  uvec4 w3 = texelFetch(u_particles, first + 3);
  vec4 i_pos_size = uintBitsToFloat(texelFetch(u_particles, first));
  vec4 i_axis_rot = uintBitsToFloat(texelFetch(u_particles, first + 1));
  vec4 i_color = uintBitsToFloat(texelFetch(u_particles, first + 2));
  vec2 i_burn_extent = uintBitsToFloat(w3.xy);
  uint i_sprite = w3.z & 0xFFu;                                // uint8 sprite (then uint8 screen priority)
  uvec2 i_soft_board = uvec2((w3.z >> 16) & 0xFFu, w3.z >> 24);  // uint8 soft_edge, uint8 billboard
#if INDEXED
  if (u_soft_override >= 0) i_soft_board.x = uint(u_soft_override);
#endif
  vec3 c = (u_view * vec4(i_pos_size.xyz, 1.0)).xyz;
  float dist = max(-c.z, u_near);
  float size = max(i_pos_size.w, kEps);
  size = min(size, max(u_size_clamp * dist * u_tan_half_y, kEps));

  float len_c = length(c);
  vec3 to_p = len_c > kEps ? c / len_c : vec3(0.0, 0.0, -1.0);
  vec3 right, up;
  float half_long = size;
  bool axis_locked = i_soft_board.y == 1u;
  vec3 a = (u_view * vec4(i_axis_rot.xyz, 0.0)).xyz;
  vec3 a_screen = a - dot(a, to_p) * to_p;  // the part of the segment seen across the view
  float a_len = length(a_screen);
  bool segment = axis_locked && a_len > kEps * max(1.0, length(a));
  if (segment) {
    up = a_screen / a_len;
    right = normalize(cross(up, to_p));
    half_long = 0.5 * a_len + size;
  } else {
    float r = axis_locked ? 0.0 : i_axis_rot.w;
    float cs = cos(r), sn = sin(r);
    right = vec3(cs, sn, 0.0);
    up = vec3(-sn, cs, 0.0);
  }
  // The sampler's level of detail across the quad's narrower side (size ≤ half_long) is at most
  // log2(texels per pixel) of a fronto-parallel quad at depth D: a camera-facing quad is one,
  // at its centre's view depth; a segment's quad is square to the view ray at distance R and
  // shows no part smaller than one at R + radius²/R (gfx/sprite_trim.h derives it).
  float r_eye = max(len_c, u_near);
  float depth = segment ? r_eye + (size * size + half_long * half_long) / r_eye : max(-c.z, u_near);
  float lod = log2(max(u_lod_scale * depth / size, 1e-30));
  int levels = textureSize(u_trim, 0).x;
  int level = u_trim_mode == 0 ? 0 : int(floor(lod + (u_trim_mode == 1 ? 0.55 : 1.05)));
  vec4 box = u_trim_mode < 0 ? vec4(0.0, 0.0, 1.0, 1.0) : texelFetch(u_trim, ivec2(clamp(level, 0, levels - 1), int(i_sprite)), 0);
  vec2 uv = vec2((gl_VertexID & 1) != 0 ? box.z : box.x, (gl_VertexID & 2) != 0 ? box.y : box.w);
  vec2 corner = vec2(2.0 * uv.x - 1.0, 1.0 - 2.0 * uv.y);
  vec3 p = c + right * (corner.x * size) + up * (corner.y * half_long);
  float extent = max(i_burn_extent.y > 0.0 ? i_burn_extent.y : size, kEps);
  // Krazanowski's volumes reach in front of the particle's mirror plane (by extent/2 for average
  // density, by the full extent for density extent); the quad moves there along the view ray,
  // which keeps its screen footprint, so the depth test cuts it only where the volume ends.
  // Bit 7 of the soft-edge byte: the renderer found no opaque mesh within this particle's reach,
  // so its soft factor is exactly 1 and the fragment shader skips the depth read.
  uint m = i_soft_board.x & 127u;
#if INDEXED
  bool clear = i_soft_board.x >= 128u || entry >= 0x80000000u;
#else
  bool clear = i_soft_board.x >= 128u;
#endif
  float push = m == 3u ? 0.5 * extent : m == 4u ? extent : 0.0;
  float pd = -p.z;
  if (push > 0.0 && pd > u_near) p *= max(pd - push, u_near * 1.001) / pd;
  gl_Position = u_proj * vec4(p, 1.0);
  v_uv = uv;
  v_color = vec4(instance_rgb(i_color), i_color.a * (1.0 - i_burn_extent.x));
  v_depth = -p.z;
  float inv_e = 1.0 / extent;
  // (zb − z − offset)·inv_e + bias with zb = lx / den: off (0) gives the constant 1, and
  // inv_extent 0 tells the fragment shader to skip the soft-edge block.
  v_soft = m == 0u || clear ? vec4(0.0, 0.0, -1.0, 0.0)
         : m == 4u ? vec4(u_linearize.x * inv_e, inv_e, 1.0, 1.0)
                   : vec4(u_linearize.x * inv_e, inv_e, 0.0, 0.0);
  v_aux = vec2(m == 2u ? 1.0 : 0.0, float(i_sprite));
}
