#include "gpu/framebuffer.hpp"

namespace plumbago::gpu {

FullscreenPass::FullscreenPass() : fbo_(make_framebuffer()), empty_(make_vertex_array()) {}

void FullscreenPass::draw(const Program& program, std::initializer_list<const Texture*> textures, Texture& target) {
  glNamedFramebufferTexture(fbo_.id(), GL_COLOR_ATTACHMENT0, target.id(), 0);
  glNamedFramebufferDrawBuffer(fbo_.id(), GL_COLOR_ATTACHMENT0);
  glBindFramebuffer(GL_FRAMEBUFFER, fbo_.id());
  glViewport(0, 0, target.width, target.height);
  GLuint unit = 0;
  for (const Texture* t : textures) glBindTextureUnit(unit++, t->id());
  glUseProgram(program.id());
  glBindVertexArray(empty_.id());
  glDrawArrays(GL_TRIANGLES, 0, 3);
  glBindVertexArray(0);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

}  // namespace plumbago::gpu
