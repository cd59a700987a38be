// The `object` style's enlarged geometry on the GPU (Nienhaus & Döllner 2004, §3.4, §4), the twin of
// reference/sketchy/sketchy_enlarged.cpp: each pixel gets the 3D noise coordinate of the
// enlarged surface it sees.
#pragma once

#include <vector>

#include "common/scene/scene.hpp"
#include "gpu/gl/gl_objects.hpp"
#include "gpu/gl/program.hpp"

namespace plumbago::gpu {

class SketchyEnlargedPass {
 public:
  // Uploads the enlarged objects (common/sketchy/sketchy.hpp enlarged_scene) once.
  explicit SketchyEnlargedPass(const Scene& enlarged);
  // `out` (RGBA32F): noise coordinate, alpha = coverage; 0 where nothing is hit.
  void render(const Camera& camera, Texture& out);

 private:
  struct Batch {
    Buffer vertices;
    VertexArray layout;
    GLsizei corners = 0;
  };
  Program program_;
  std::vector<Batch> batches_;
  Framebuffer fbo_;
  Renderbuffer depth_test_;
};

}  // namespace plumbago::gpu
