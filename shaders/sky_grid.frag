#version 330 core
// The nebula colour interpolated across a grid cell (sky_grid.vert).
in vec3 v_color;
out vec4 o_color;
void main() { o_color = vec4(v_color, 1.0); }
