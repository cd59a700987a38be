#include "gpu/compose.hpp"

namespace plumbago::gpu {

ComposePass::ComposePass() : program_("fullscreen.vert", "compose.frag", glsl_params<ComposeParams>()) {
  glProgramUniform1i(program_.id(), program_.uniform("contour_darkness"), 0);
  glProgramUniform1i(program_.id(), program_.uniform("interior_darkness"), 1);
  glProgramUniform1i(program_.id(), program_.uniform("paper_color"), 2);
}

void ComposePass::run(const Texture& contour_darkness, bool has_contours, const Texture& interior_darkness,
                      bool has_interior, const Texture& paper_color, bool has_paper, const ComposeParams& p,
                      Texture& out) {
  program_.set_params(p);
  glProgramUniform1i(program_.id(), program_.uniform("has_contours"), has_contours);
  glProgramUniform1i(program_.id(), program_.uniform("has_interior"), has_interior);
  glProgramUniform1i(program_.id(), program_.uniform("has_paper"), has_paper);
  pass_.draw(program_, {&contour_darkness, &interior_darkness, &paper_color}, out);
}

}  // namespace plumbago::gpu
