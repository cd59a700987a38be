#include "gpu/compose.hpp"

namespace plumbago::gpu {

ComposePass::ComposePass() : program_("fullscreen.vert", "compose.frag", glsl_params<ComposeParams>()) {
  glProgramUniform1i(program_.id(), program_.uniform("contour_darkness"), 0);
  glProgramUniform1i(program_.id(), program_.uniform("interior_darkness"), 1);
  glProgramUniform1i(program_.id(), program_.uniform("paper_color"), 2);
}

void ComposePass::set_uniforms(bool has_contours, bool has_interior, bool has_paper, const ComposeParams& p) {
  program_.set_params(p);
  glProgramUniform1i(program_.id(), program_.uniform("has_contours"), has_contours);
  glProgramUniform1i(program_.id(), program_.uniform("has_interior"), has_interior);
  glProgramUniform1i(program_.id(), program_.uniform("has_paper"), has_paper);
}

// The composition of D_c = D_i = 0 (enhanced(1) = 1, so the paper color itself), drawn
// by the same shader.
const Texture& ComposePass::blank_page(const Texture& paper_color, bool has_paper, const ComposeParams& p,
                                       const Texture& out) {
  GLuint paper = has_paper ? paper_color.id() : 0;
  if (page_.width == out.width && page_.height == out.height && page_paper_ == paper) return page_;
  page_ = make_texture(out.width, out.height, out.internal_format);
  page_paper_ = paper;
  set_uniforms(false, false, has_paper, p);
  pass_.draw(program_, {&paper_color, &paper_color, &paper_color}, page_);
  return page_;
}

void ComposePass::run(const Texture& contour_darkness, bool has_contours, const Texture& interior_darkness,
                      bool has_interior, const Texture& paper_color, bool has_paper, const ComposeParams& p,
                      Texture& out, const PixelRect& inside) {
  const Texture& page = blank_page(paper_color, has_paper, p, out);
  glCopyImageSubData(page.id(), GL_TEXTURE_2D, 0, 0, 0, 0, out.id(), GL_TEXTURE_2D, 0, 0, 0, 0, out.width, out.height, 1);
  set_uniforms(has_contours, has_interior, has_paper, p);
  pass_.draw_inside(program_, {&contour_darkness, &interior_darkness, &paper_color}, {&out}, inside, {});
}

}  // namespace plumbago::gpu
