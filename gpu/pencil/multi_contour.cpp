#include "gpu/pencil/multi_contour.hpp"

#include <cmath>
#include <stdexcept>

#include "gpu/core/stage.hpp"

namespace plumbago::gpu {

ContourInputs make_contour_inputs(const ContourParams& p, const std::vector<Image>& grids, const Image& contour_texture,
                                  const std::vector<glm::vec2>& shifts, int width, int height) {
  if (size_t(p.copies) > grids.size() || size_t(p.copies) > shifts.size())
    throw std::invalid_argument("multi_contour: fewer offset grids or texture shifts than contour.copies");
  Texture offset_grids = upload_texture_3d(grids, GL_RG32F, GL_TEXTURE_2D_ARRAY),
          texture = upload_texture(contour_texture, GL_R32F);
  set_sampling(offset_grids, GL_LINEAR, GL_CLAMP_TO_EDGE, GL_CLAMP_TO_EDGE);
  set_sampling(texture, GL_LINEAR, GL_REPEAT, GL_REPEAT);
  Program program("util/fullscreen.vert", "pencil/contour_copies.frag", glsl_params<ContourParams>());
  program.set_params(p);
  ContourInputs in{make_texture_array(width, height, p.copies, GL_RGBA32F), largest_offset(grids)};
  FullscreenPass pass;
  for (int k = 0; k < p.copies; ++k) {
    glProgramUniform1i(program.id(), program.uniform("copy"), k);
    glProgramUniform2fv(program.id(), program.uniform("texture_shift"), 1, &shifts[size_t(k)].x);
    pass.draw_layer(program, {{"offset_grids", &offset_grids}, {"contour_texture", &texture}}, in.copy_inputs, k);
  }
  return in;
}

namespace {
// How many blocks away a pixel's copies can read. A copy of pixel p reads d' bilinearly at
// p + offset, |offset| <= reach = largest_offset + 0.5 (a bilinearly filtered offset can
// exceed its corners' largest value by a rounding error, never by that much): texels
// floor(p - reach - 0.5) to floor(p + reach - 0.5) + 1. With p = 8b + 0.5 + i (kContourBlock = 8), i in 0..7,
// that is from 8b - ceil(reach) to 8b + 8 + floor(reach): blocks b - D to b + D with
// D = 1 + floor(reach / 8).
int block_reach(float largest_offset) { return 1 + int(std::floor((largest_offset + 0.5f) / float(kContourBlock))); }
}  // namespace

std::string multi_contour_prelude() { return glsl_params<ContourParams>() + contour_block_define(); }

MultiContourPass::MultiContourPass()
    : program_("util/fullscreen.vert", "pencil/multi_contour.frag", multi_contour_prelude()),
      blocks_program_("util/fullscreen.vert", "pencil/contour_blocks.frag", contour_block_define()),
      reach_program_("util/fullscreen.vert", "pencil/contour_block_reach.frag") {}

void MultiContourPass::mark_blocks(const Texture& lit, Texture& marks) {
  pass_.draw(blocks_program_, {{"lit_contour_darkness", &lit}}, marks);
}

ContourSources MultiContourPass::prepare(const Texture& lit, const ContourInputs& in, const ContourParams& p,
                                         const Texture* marks) {
  if (p.copies > in.copy_inputs.depth || in.copy_inputs.width != lit.width || in.copy_inputs.height != lit.height)
    throw std::invalid_argument("multi_contour: the copies' inputs were made for another size or fewer copies");
  set_sampling(lit, GL_LINEAR, GL_CLAMP_TO_EDGE, GL_CLAMP_TO_EDGE);
  fit_to_blocks(block_reach_max_, lit.width, lit.height);
  if (marks) {
    glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT);  // the marks were stored as an image
  } else {
    fit_to_blocks(block_marks_, lit.width, lit.height);
    mark_blocks(lit, block_marks_);
    marks = &block_marks_;
  }
  glProgramUniform1i(reach_program_.id(), reach_program_.uniform("block_reach"), block_reach(in.largest_offset));
  pass_.draw(reach_program_, {{"block_marks", marks}}, block_reach_max_);
  return {lit, in.copy_inputs, block_reach_max_, p};
}

void MultiContourPass::run(const Texture& lit, const ContourInputs& in, const ContourParams& p, Texture& out,
                           const PixelRect& covered) {
  ContourSources s = prepare(lit, in, p);
  program_.set_params(p);
  pass_.draw_inside(
      program_,
      {{"lit_contour_darkness", &s.lit}, {"copy_inputs", &s.copy_inputs}, {"block_reach_max", &s.block_reach_max}},
      {&out}, covered, {glm::vec4(0.0f)});
}

ContourInputs make_contour_inputs(const GpuFrame& f) {
  return make_contour_inputs(f.params<ContourParams>(), f.get(kOffsetGrids), f.get(kContourTexture),
                             f.get(kTextureShifts), f.scene.width, f.scene.height);
}

namespace {

// Multiple contours drawn into their own target: a frame that composes them draws them
// in the composition pass instead (gpu/pencil/compose.cpp).
class MultiContourStagePass : public GpuPass {
 public:
  explicit MultiContourStagePass(GpuFrame& f) : inputs_(make_contour_inputs(f)) {}
  void run(GpuFrame& f) override {
    pass_.run(f.get(kLitContourDarkness), inputs_, f.params<ContourParams>(), f.put(kCopiesDarkness),
              contour_rect(f.ordinary, f.get(kOffsetGrids)));
  }

 private:
  ContourInputs inputs_;
  MultiContourPass pass_;
};

}  // namespace

PLUMBAGO_GPU_PASS(multi_contour, {{"multi_contour"}, {}, make_pass<MultiContourStagePass>, Probe::Fetch3x3});

}  // namespace plumbago::gpu
