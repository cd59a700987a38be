#include "gpu/multi_contour.hpp"

#include <stdexcept>

namespace plumbago::gpu {

ContourInputs upload_contour_inputs(const std::vector<Image>& grids, const Image& contour_texture,
                                    std::vector<glm::vec2> shifts) {
  ContourInputs in{upload_texture_3d(grids, GL_RG32F, GL_TEXTURE_2D_ARRAY), upload_texture(contour_texture, GL_R32F),
                   std::move(shifts), largest_offset(grids)};
  set_sampling(in.offset_grids, GL_LINEAR, GL_CLAMP_TO_EDGE, GL_CLAMP_TO_EDGE);
  set_sampling(in.contour_texture, GL_LINEAR, GL_REPEAT, GL_REPEAT);
  return in;
}

namespace {
constexpr int kBlock = 8;  // pixels per side of a block of contour_blocks.frag
const std::string kBlockDefine = "#define CONTOUR_BLOCK " + std::to_string(kBlock) + "\n";
}  // namespace

MultiContourPass::MultiContourPass()
    : program_("fullscreen.vert", "multi_contour.frag", glsl_params<ContourParams>() + kBlockDefine),
      blocks_program_("fullscreen.vert", "contour_blocks.frag", kBlockDefine) {
  glProgramUniform1i(program_.id(), program_.uniform("lit_contour_darkness"), 0);
  glProgramUniform1i(program_.id(), program_.uniform("offset_grids"), 1);
  glProgramUniform1i(program_.id(), program_.uniform("contour_texture"), 2);
  glProgramUniform1i(program_.id(), program_.uniform("block_max"), 3);
}

void MultiContourPass::run(const Texture& lit, const ContourInputs& in, const ContourParams& p, Texture& out,
                           const PixelRect& covered) {
  if (p.copies > 8 || size_t(p.copies) > in.shifts.size())
    throw std::invalid_argument("multi_contour: the inputs hold fewer copies than contour.copies");
  program_.set_params(p);
  glProgramUniform2fv(program_.id(), program_.uniform("texture_shift"), GLsizei(p.copies), &in.shifts[0].x);
  set_sampling(lit, GL_LINEAR, GL_CLAMP_TO_EDGE, GL_CLAMP_TO_EDGE);
  int blocks_x = (lit.width + kBlock - 1) / kBlock, blocks_y = (lit.height + kBlock - 1) / kBlock;
  if (block_max_.width != blocks_x || block_max_.height != blocks_y) block_max_ = make_texture(blocks_x, blocks_y, GL_R32F);
  pass_.draw(blocks_program_, {&lit}, block_max_);
  // Half a pixel more than the largest offset: a bilinearly filtered offset can exceed its
  // corners' largest value by a rounding error, never by that much.
  glProgramUniform1f(program_.id(), program_.uniform("reach"), in.largest_offset + 0.5f);
  pass_.draw_inside(program_, {&lit, &in.offset_grids, &in.contour_texture, &block_max_}, {&out}, covered,
                    {glm::vec4(0.0f)});
}

}  // namespace plumbago::gpu
