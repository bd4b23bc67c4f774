// gfx/color_space.h — sRGB transfer functions and the sprite conversion for the HDR scene (no GL).
//
// Colours in Arcfire's data (effect colours, sprites, albedo textures, material and team
// colours, the nebula) were picked on screen, so they are sRGB-encoded. With render.hdr on the
// renderer works in linear light: it decodes them (textures in the sampler, as GL_SRGB8_ALPHA8;
// uniforms here; particle colours in particle.vert) and encodes once, in the tone-map pass.
// Premultiplication must happen in linear light: premultiply_linear_srgb() takes a sprite's
// straight colour, decodes it, multiplies by alpha and encodes it again, so the sampler's
// decode gives exactly linear(c)·a.
//
// Example, compiled as GfxCpuExamples.LinearLight in tests/unit/gfx/test_gfx_cpu_examples.cpp:
//   glm::vec3 lin = srgb_to_linear(glm::vec3(1.0f, 0.55f, 0.2f));
//   Image texels = premultiply_linear_srgb(load_image("assets/textures/sprite_smoke.png"));
#pragma once
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "assets/model.h"

namespace arc {

// IEC 61966-2-1 piecewise curves; values above 1 follow the power segment (HDR colours).
float srgb_to_linear(float c);
float linear_to_srgb(float c);
glm::vec3 srgb_to_linear(glm::vec3 c);
glm::vec4 srgb_to_linear(glm::vec4 c);  // alpha unchanged

// Straight or premultiplied RGBA8 (Image::premultiplied says which) to premultiplied-in-linear
// texels stored sRGB-encoded, for an GL_SRGB8_ALPHA8 texture. A premultiplied input is
// divided by its alpha first (exact for opaque texels and for white sprites).
Image premultiply_linear_srgb(const Image& image);

}  // namespace arc
