#include "gpu/multi_contour.hpp"

#include <stdexcept>

namespace plumbago::gpu {

ContourInputs upload_contour_inputs(const std::vector<Image>& grids, const Image& contour_texture,
                                    std::vector<glm::vec2> shifts) {
  ContourInputs in{upload_texture_3d(grids, GL_RG32F, GL_TEXTURE_2D_ARRAY), upload_texture(contour_texture, GL_R32F),
                   std::move(shifts)};
  set_sampling(in.offset_grids, GL_LINEAR, GL_CLAMP_TO_EDGE, GL_CLAMP_TO_EDGE);
  set_sampling(in.contour_texture, GL_LINEAR, GL_REPEAT, GL_REPEAT);
  return in;
}

MultiContourPass::MultiContourPass() : program_("fullscreen.vert", "multi_contour.frag", glsl_params<ContourParams>()) {
  glProgramUniform1i(program_.id(), program_.uniform("lit_contour_darkness"), 0);
  glProgramUniform1i(program_.id(), program_.uniform("offset_grids"), 1);
  glProgramUniform1i(program_.id(), program_.uniform("contour_texture"), 2);
}

void MultiContourPass::run(const Texture& lit, const ContourInputs& in, const ContourParams& p, Texture& out,
                           const PixelRect& covered) {
  if (p.copies > 8 || size_t(p.copies) > in.shifts.size())
    throw std::invalid_argument("multi_contour: the inputs hold fewer copies than contour.copies");
  program_.set_params(p);
  glProgramUniform2fv(program_.id(), program_.uniform("texture_shift"), GLsizei(p.copies), &in.shifts[0].x);
  set_sampling(lit, GL_LINEAR, GL_CLAMP_TO_EDGE, GL_CLAMP_TO_EDGE);
  pass_.draw_inside(program_, {&lit, &in.offset_grids, &in.contour_texture}, {&out}, covered, {glm::vec4(0.0f)});
}

}  // namespace plumbago::gpu
