// The paper effect of stroke-based rendering on the GPU (SPEC 4.2), the twin of
// reference/stroke_paper.cpp: a full-window pass over the coat and the paper's height.
#include "common/stroke_paper.hpp"

#include "gpu/framebuffer.hpp"
#include "gpu/stage.hpp"

namespace plumbago::gpu {

namespace {

class StrokePaperPass : public GpuPass {
 public:
  explicit StrokePaperPass(GpuFrame& f)
      : program_("fullscreen.vert", "stroke_paper.frag", glsl_params<StrokePaperParams>()),
        height_(upload_texture(f.pre.paper.height, GL_R32F)) {}
  void run(GpuFrame& f) override {
    program_.set_params(f.params<StrokePaperParams>());
    pass_.draw(program_, {{"coat", &f.input("basecoat.coat")}, {"paper_height", &height_}}, f.output("stroke_paper.color"));
  }

 private:
  Program program_;
  FullscreenPass pass_;
  Texture height_;
};

}  // namespace

PLUMBAGO_GPU_PASS(stroke_paper, {{"stroke_paper"}, {}, make_pass<StrokePaperPass>});

}  // namespace plumbago::gpu
