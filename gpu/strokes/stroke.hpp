// The stroke samples as the GPU's ribbons read them (shaders/strokes/common_ribbon.glsl): what
// gpu/strokes/stroke.cpp draws from, and what tests read its ribbon corners against the
// reference's (common/strokes/base_stroke.hpp 6.) through.
#pragma once

#include <cstdint>
#include <vector>

#include "common/strokes/stroke.hpp"
#include "gpu/gl/gl_objects.hpp"

namespace plumbago::gpu {

// One sample (std430).
struct SampleRecord {
  glm::vec2 position;  // window px, offset applied
  float u, width, alpha;
  uint32_t run, pen_down_after, pad = 0;
};
// One run: its color and stroke texture layer, its samples, whether it is drawn as a loop.
struct RunRecord {
  glm::vec4 color_layer;
  uint32_t first, count, cyclic, pad = 0;
};
static_assert(sizeof(SampleRecord) == 32 && sizeof(RunRecord) == 32, "std430 layouts of common_ribbon.glsl");

// The samples of every run that draws a ribbon (common/strokes/base_stroke.hpp ribbon: 2 or
// more), in GPU buffers bound as common_ribbon.glsl reads them.
class RibbonBuffers {
 public:
  explicit RibbonBuffers(const std::vector<RunStroke>& strokes);
  // Six a sample: the two triangles to the next one.
  GLsizei vertices() const { return vertices_; }
  // To SSBO bindings 0 (samples) and 1 (runs).
  void bind() const;

 private:
  Buffer samples_, runs_;
  GLsizei vertices_ = 0;
};

}  // namespace plumbago::gpu
