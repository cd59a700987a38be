#version 450 core
// Perspective-correct interpolation gives the noise coordinate the ray tracer's
// barycentrics give (reference/sketchy/sketchy_enlarged.cpp).
in vec3 v_noise_coordinate;

layout(location = 0) out vec4 noise_coordinate;  // alpha = coverage

void main() { noise_coordinate = vec4(v_noise_coordinate, 1.0); }
