#version 330 core
// The half-resolution particle target over the scene (gfx/particle_target.h): rgb is the
// particles' summed premultiplied light, alpha the transmittance left; blended with
// GL_ONE, GL_SRC_ALPHA the scene becomes rgb + alpha·scene. Bilinear filtering is exact for
// both (they are linear in what they sum).
in vec2 v_uv;
uniform sampler2D u_particles;
out vec4 o_color;

void main() { o_color = texture(u_particles, v_uv); }
