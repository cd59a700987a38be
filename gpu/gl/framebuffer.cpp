#include "gpu/gl/framebuffer.hpp"

#include <algorithm>

namespace plumbago::gpu {

FullscreenPass::FullscreenPass() : fbo_(make_framebuffer()), empty_(make_vertex_array()) {}

void FullscreenPass::draw(const Program& program, std::initializer_list<TextureBinding> textures, Texture& target) {
  draw(program, textures, {&target});
}

void FullscreenPass::draw(const Program& program, std::initializer_list<TextureBinding> textures,
                          std::initializer_list<Texture*> targets) {
  bind_targets(targets);
  draw_triangle(program, textures);
}

void FullscreenPass::draw_inside(const Program& program, std::initializer_list<TextureBinding> textures,
                                 std::initializer_list<Texture*> targets, const PixelRect& rect,
                                 std::initializer_list<glm::vec4> outside) {
  bind_targets(targets);
  GLint k = 0;
  for (const glm::vec4& v : outside) glClearBufferfv(GL_COLOR, k++, &v.x);
  glEnable(GL_SCISSOR_TEST);
  glScissor(rect.x0, rect.y0, std::max(0, rect.x1 - rect.x0), std::max(0, rect.y1 - rect.y0));
  draw_triangle(program, textures);
  glDisable(GL_SCISSOR_TEST);
}

void FullscreenPass::bind_targets(std::initializer_list<Texture*> targets) {
  glBindFramebuffer(GL_FRAMEBUFFER, fbo_.id());
  GLsizei n = 0;
  for (Texture* t : targets)
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0 + GLenum(n++), GL_TEXTURE_2D, t->id(), 0);
  use_attachments(n, **targets.begin());
}

void FullscreenPass::draw_layer(const Program& program, std::initializer_list<TextureBinding> textures, Texture& array,
                                int layer) {
  glBindFramebuffer(GL_FRAMEBUFFER, fbo_.id());
  glFramebufferTextureLayer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, array.id(), 0, layer);
  use_attachments(1, array);
  draw_triangle(program, textures);
}

// Draws into the first n color attachments (the others detached), all of `first`'s size.
void FullscreenPass::use_attachments(GLsizei n, const Texture& first) {
  GLenum buffers[8];
  for (GLsizei k = 0; k < 8; ++k) {
    buffers[k] = GL_COLOR_ATTACHMENT0 + GLenum(k);
    if (k >= n) glFramebufferTexture2D(GL_FRAMEBUFFER, buffers[k], GL_TEXTURE_2D, 0, 0);
  }
  glDrawBuffers(n, buffers);
  glViewport(0, 0, first.width, first.height);
}

// Binds `textures` to their samplers and draws the full-window triangle into the bound targets.
void FullscreenPass::draw_triangle(const Program& program, std::initializer_list<TextureBinding> textures) {
  bind_textures(program, textures);
  glUseProgram(program.id());
  glBindVertexArray(empty_.id());
  glDrawArrays(GL_TRIANGLES, 0, 3);
  glBindVertexArray(0);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

}  // namespace plumbago::gpu
