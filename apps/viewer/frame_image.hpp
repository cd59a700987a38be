// The rendered frame in the window: a texture of the window's context, blitted centered,
// 1:1 or shrunk to fit.
#pragma once

#include <glm/glm.hpp>

#include "common/util/image.hpp"
#include "gpu/gl/gl_objects.hpp"

namespace plumbago {

// Where the frame lies in a framebuffer: lower-left corner and size, in pixels.
struct Placement {
  glm::ivec2 origin{0}, size{0};
};
Placement place(glm::ivec2 frame, glm::ivec2 framebuffer);

class FrameImage {
 public:
  void show(const Image& color);  // RGB, row 0 at the bottom
  // Clears the window's framebuffer and blits the frame to `where` in it.
  void draw(glm::ivec2 framebuffer, const Placement& where) const;
  glm::ivec2 size() const { return {texture_.width, texture_.height}; }

 private:
  gpu::Texture texture_;
  gpu::Framebuffer read_;
};

}  // namespace plumbago
