// Full-window passes: draw one triangle into a texture, every fragment at a pixel center.
#pragma once

#include "gpu/gl_objects.hpp"
#include "gpu/program.hpp"

namespace plumbago::gpu {

class FullscreenPass {
 public:
  FullscreenPass();
  // Binds `textures` to units 0.. in order, then draws `program` into `target`.
  void draw(const Program& program, std::initializer_list<const Texture*> textures, Texture& target);

 private:
  Framebuffer fbo_;
  VertexArray empty_;
};

}  // namespace plumbago::gpu
