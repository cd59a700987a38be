// The stroke samples as the GPU's ribbons read them (shaders/strokes/common_ribbon.glsl): what
// gpu/strokes/stroke_samples.hpp writes and gpu/strokes/stroke.cpp draws from.
#pragma once

#include <glm/glm.hpp>

#include <cstdint>

namespace plumbago::gpu {

// One sample (std430).
struct SampleRecord {
  glm::vec2 position;  // window px, offset applied
  float u, width, alpha;
  uint32_t run, pen_down_after;
  uint32_t ribbon = 0;     // the segment to the next sample draws (the GPU writes it)
  glm::vec2 normal{0.0F};  // the ribbon's vertex normal (the GPU writes it)
};
// One run: its color and stroke texture layer, its samples, whether it is drawn as a loop.
struct RunRecord {
  glm::vec4 color_layer;
  uint32_t first, count, cyclic, pad = 0;
};
static_assert(sizeof(SampleRecord) == 40 && sizeof(RunRecord) == 32, "std430 layouts of common_ribbon.glsl");

}  // namespace plumbago::gpu
