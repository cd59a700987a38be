#include "apps/viewer/frame_image.hpp"

#include <algorithm>
#include <cmath>

namespace plumbago {

Placement place(glm::ivec2 frame, glm::ivec2 framebuffer) {
  if (frame.x <= 0 || frame.y <= 0) return {};
  // Shrunk to fit, never enlarged: at 1:1 the window shows the frame's pixels exactly.
  float scale = std::min({1.0f, float(framebuffer.x) / float(frame.x), float(framebuffer.y) / float(frame.y)});
  glm::ivec2 size(std::lround(float(frame.x) * scale), std::lround(float(frame.y) * scale));
  return {(framebuffer - size) / 2, size};
}

void FrameImage::show(const Image& color) {
  if (color.width != texture_.width || color.height != texture_.height) {
    // RGBA: a read framebuffer needs a color-renderable attachment, which RGB32F is not.
    texture_ = gpu::make_texture(color.width, color.height, GL_RGBA32F);
    GLuint fbo = 0;
    glCreateFramebuffers(1, &fbo);
    read_ = gpu::Framebuffer(fbo);
    glNamedFramebufferTexture(fbo, GL_COLOR_ATTACHMENT0, texture_.id(), 0);
  }
  gpu::write_texture(texture_, color.channels, false, color.data.data());
}

void FrameImage::draw(glm::ivec2 framebuffer, const Placement& p) const {
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, 0);
  glViewport(0, 0, framebuffer.x, framebuffer.y);
  glClearColor(0.25f, 0.25f, 0.27f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT);
  if (!read_.id()) return;
  GLenum filter = p.size == size() ? GL_NEAREST : GL_LINEAR;
  glBlitNamedFramebuffer(read_.id(), 0, 0, 0, texture_.width, texture_.height, p.origin.x, p.origin.y,
                         p.origin.x + p.size.x, p.origin.y + p.size.y, GL_COLOR_BUFFER_BIT, filter);
}

}  // namespace plumbago
