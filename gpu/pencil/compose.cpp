#include "gpu/pencil/compose.hpp"

#include "gpu/core/stage.hpp"

namespace plumbago::gpu {

ComposePass::ComposePass()
    : programs_("util/fullscreen.vert", "pencil/compose.frag", glsl_params<ComposeParams>() + multi_contour_prelude(),
                {"MULTI_CONTOUR", "WRITE_CONTOUR_DARKNESS"}) {}

const Program& ComposePass::program(bool draws_contours, bool writes_contours, bool has_contours,
                                    const ComposeInputs& in, const ComposeParams& p) {
  const Program& made = programs_.get({draws_contours, writes_contours});
  made.set_params(p);
  glProgramUniform1i(made.id(), made.uniform("has_contours"), has_contours);
  glProgramUniform1i(made.id(), made.uniform("has_interior"), in.has_interior);
  glProgramUniform1i(made.id(), made.uniform("has_paper"), in.has_paper);
  return made;
}

// The composition of D_c = D_i = 0 (enhanced(1) = 1, so the paper color itself), drawn
// by the same shader.
void ComposePass::copy_blank_page(const ComposeInputs& in, const ComposeParams& p, Texture& out) {
  GLuint paper = in.has_paper ? in.paper_color.id() : 0;
  if (page_.width != out.width || page_.height != out.height || page_paper_ != paper) {
    page_ = make_texture(out.width, out.height, out.internal_format);
    page_paper_ = paper;
    ComposeInputs blank{in.paper_color, false, in.paper_color, in.has_paper};
    pass_.draw(program(false, false, false, blank, p),
               {{"interior_darkness", &in.paper_color},
                {"paper_color", &in.paper_color},
                {"contour_darkness", &in.paper_color}},
               page_);
  }
  glCopyImageSubData(page_.id(), GL_TEXTURE_2D, 0, 0, 0, 0, out.id(), GL_TEXTURE_2D, 0, 0, 0, 0, out.width, out.height,
                     1);
}

void ComposePass::run(const Texture& contour_darkness, bool has_contours, const ComposeInputs& in,
                      const ComposeParams& p, Texture& out, const PixelRect& inside) {
  copy_blank_page(in, p, out);
  pass_.draw_inside(program(false, false, has_contours, in, p),
                    {{"interior_darkness", &in.interior_darkness},
                     {"paper_color", &in.paper_color},
                     {"contour_darkness", &contour_darkness}},
                    {&out}, inside, {});
}

void ComposePass::run(const ContourSources& c, const ComposeInputs& in, const ComposeParams& p, Texture& out,
                      const PixelRect& inside, Texture* contour_darkness) {
  copy_blank_page(in, p, out);
  const Program& made = program(true, contour_darkness != nullptr, true, in, p);
  made.set_params(c.params);
  std::initializer_list<TextureBinding> textures = {{"interior_darkness", &in.interior_darkness},
                                                    {"paper_color", &in.paper_color},
                                                    {"lit_contour_darkness", &c.lit},
                                                    {"copy_inputs", &c.copy_inputs},
                                                    {"block_reach_max", &c.block_reach_max}};
  if (contour_darkness)
    pass_.draw_inside(made, textures, {&out, contour_darkness}, inside, {});
  else
    pass_.draw_inside(made, textures, {&out}, inside, {});
}

namespace {

// What the composition reads besides D_c, as the frame made it: D_i where the interior
// runs, the paper color where the paper does (1x1 stand-ins, not read, otherwise).
class ComposeStagePass : public GpuPass {
 public:
  explicit ComposeStagePass(GpuFrame& f)
      : paper_color_(f.get(maybe(kPaperColor)) ? upload_texture(f.get(kPaperColor), GL_RGBA32F)
                                               : make_texture(1, 1, GL_RGBA32F)),
        has_paper_(f.get(maybe(kPaperColor)) != nullptr),
        none_(make_texture(1, 1, GL_R32F)) {}

 protected:
  ComposeInputs inputs(const GpuFrame& f) const {
    const Texture* interior = f.get(maybe(kInteriorDarkness));
    return {interior ? *interior : none_, interior != nullptr, paper_color_, has_paper_};
  }
  // Where D_c or D_i can differ from 0: around the contours' reach, or the objects.
  PixelRect inside(const GpuFrame& f) const {
    if (f.dump) return {0, 0, f.scene.width, f.scene.height};
    return f.ran("multi_contour") ? contour_rect(f.ordinary, f.get(kOffsetGrids)) : f.filter_rect(0);
  }
  ComposePass pass_;
  Texture paper_color_;
  bool has_paper_;
  Texture none_;
};

// The composition alone: of D_c where a pass wrote it (parity), else of no contours.
class ComposeAlonePass : public ComposeStagePass {
 public:
  using ComposeStagePass::ComposeStagePass;
  void run(GpuFrame& f) override {
    const Texture* contours = f.get(maybe(kCopiesDarkness));
    pass_.run(contours ? *contours : none_, contours != nullptr, inputs(f), f.params<ComposeParams>(),
              f.put(kComposeColor), inside(f));
  }
};

// The composition drawing the multiple contours itself (compose.frag MULTI_CONTOUR): no D_c
// target written and read in a frame; a dump also keeps D_c.
class ContoursInComposePass : public ComposeStagePass {
 public:
  explicit ContoursInComposePass(GpuFrame& f) : ComposeStagePass(f), contour_inputs_(make_contour_inputs(f)) {}
  void run(GpuFrame& f) override {
    ContourSources contours = contours_.prepare(f.get(kLitContourDarkness), contour_inputs_, f.params<ContourParams>(),
                                                f.get(maybe(kContourBlockMarks)));
    pass_.run(contours, inputs(f), f.params<ComposeParams>(), f.put(kComposeColor), inside(f),
              f.dump ? &f.put(kCopiesDarkness) : nullptr);
  }

 private:
  ContourInputs contour_inputs_;
  MultiContourPass contours_;
};

}  // namespace

PLUMBAGO_GPU_PASS(compose, {{"compose"}, {}, make_pass<ComposeAlonePass>});
PLUMBAGO_GPU_PASS(multi_contour_compose, {{"multi_contour", "compose"},
                                          {kCopiesDarkness.name},
                                          make_pass<ContoursInComposePass>,
                                          Probe::Fetch3x3});

}  // namespace plumbago::gpu
