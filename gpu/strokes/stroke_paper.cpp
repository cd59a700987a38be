// The paper effect of stroke-based rendering on the GPU (Kalnins et al. 2002, §4.4), the twin of
// reference/strokes/stroke_paper.cpp: a full-window pass over the G-buffer's ids, the coat and
// the paper's height, drawn in place over what the other pipelines drew.
#include "common/strokes/stroke_paper.hpp"

#include "gpu/gl/framebuffer.hpp"
#include "gpu/core/stage.hpp"

namespace plumbago::gpu {

namespace {

class StrokePaperPass : public GpuPass {
 public:
  explicit StrokePaperPass(GpuFrame& f)
      : program_("util/fullscreen.vert", "strokes/stroke_paper.frag", glsl_params<StrokePaperParams>()),
        height_(upload_texture(f.pre.paper.height, GL_R32F)),
        none_(upload_texture(Image(1, 1, 4), GL_RGBA8)) {
    std::vector<uint32_t> flags = stroke_object_flags(f.ordinary);
    flags.push_back(0);  // never empty
    strokes_ = make_buffer(flags.data(), flags.size() * sizeof(uint32_t));
    GBufferChannels read = GBufferChannels::none();
    read.read_region = {0, 0, f.scene.width, f.scene.height};
    f.read_gbuffer("gbuffer", read);
  }
  void run(GpuFrame& f) override {
    Texture& target = f.output("stroke_paper.color");
    if (drawn_over(find_output("stroke_paper.color"), f.stages).empty()) {
      const float white[4] = {1, 1, 1, 1};
      glClearTexImage(target.id(), 0, GL_RGBA, GL_FLOAT, white);
    }
    bool coat = f.has("basecoat.coat"), sprite = f.has("sketchy_composite.depth");
    glProgramUniform1i(program_.id(), program_.uniform("has_coat"), coat);
    glProgramUniform1i(program_.id(), program_.uniform("has_sprite"), sprite);
    program_.set_params(f.params<StrokePaperParams>());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, strokes_.id());
    // Only where the G-buffer's objects can be: elsewhere every pixel keeps what is under.
    pass_.draw_inside(program_,
                      {{"ids", &f.shared<GBufferTargets>("gbuffer").ids},
                       {"coat", coat ? &f.input("basecoat.coat") : &none_},
                       {"sprite_depth", sprite ? &f.input("sketchy_composite.depth") : &none_},
                       {"paper_height", &height_}},
                      {&target}, filter_rect(f.ordinary, 0), {});
  }

 private:
  Program program_;
  FullscreenPass pass_;
  Texture height_, none_;
  Buffer strokes_;
};

}  // namespace

PLUMBAGO_GPU_PASS(stroke_paper, {{"stroke_paper"}, {}, make_pass<StrokePaperPass>});

}  // namespace plumbago::gpu
