#version 450 core
// The `object` style's enlarged geometry (Nienhaus & Döllner §4.2-4.3): world
// positions of the enlarged triangle soup and each corner's 3D noise coordinate.
layout(location = 0) in vec3 position;          // world
layout(location = 1) in vec3 noise_coordinate;  // enlarged object space / bbox diagonal

uniform mat4 view;
uniform mat4 projection;

out vec3 v_noise_coordinate;

void main() {
  gl_Position = projection * (view * vec4(position, 1.0));  // as gbuffer.vert
  v_noise_coordinate = noise_coordinate;
}
