#include "gpu/framebuffer.hpp"

namespace plumbago::gpu {

FullscreenPass::FullscreenPass() : fbo_(make_framebuffer()), empty_(make_vertex_array()) {}

void FullscreenPass::draw(const Program& program, std::initializer_list<const Texture*> textures, Texture& target) {
  glBindFramebuffer(GL_FRAMEBUFFER, fbo_.id());
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, target.id(), 0);
  GLenum color0 = GL_COLOR_ATTACHMENT0;
  glDrawBuffers(1, &color0);
  glViewport(0, 0, target.width, target.height);
  bind_textures(textures);
  glUseProgram(program.id());
  glBindVertexArray(empty_.id());
  glDrawArrays(GL_TRIANGLES, 0, 3);
  glBindVertexArray(0);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

}  // namespace plumbago::gpu
