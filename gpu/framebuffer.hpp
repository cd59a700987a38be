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
  // The same into several targets of one size: fragment output k goes to targets[k].
  void draw(const Program& program, std::initializer_list<const Texture*> textures,
            std::initializer_list<Texture*> targets);

 private:
  Framebuffer fbo_;
  VertexArray empty_;
};

}  // namespace plumbago::gpu
