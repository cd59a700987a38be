// The paper effect of stroke-based rendering on the GPU (Kalnins et al. 2002, §4.4), the twin of
// reference/strokes/stroke_paper.cpp: a full-window pass over the G-buffer's ids, the coat and
// the paper's height, drawn in place over what the other pipelines drew.
#include "common/strokes/stroke_paper.hpp"

#include "gpu/core/stage.hpp"
#include "gpu/gl/framebuffer.hpp"

namespace plumbago::gpu {

namespace {

class StrokePaperPass : public GpuPass {
 public:
  explicit StrokePaperPass(GpuFrame& f)
      : program_("util/fullscreen.vert", "strokes/stroke_paper.frag", glsl_params<StrokePaperParams>()),
        height_(upload_texture(f.get(kPaperHeight), GL_R32F)),
        none_(upload_texture(Image(1, 1, 4), GL_RGBA8)) {
    std::vector<uint32_t> flags = stroke_object_flags(f.ordinary);
    flags.push_back(0);  // never empty
    strokes_ = make_buffer(flags.data(), flags.size() * sizeof(uint32_t));
    f.read_region(kGBuffer, {0, 0, f.scene.width, f.scene.height});
  }
  void run(GpuFrame& f) override {
    Texture& target = f.put(kPage);
    if (drawn_over(find_output(kPage.name), f.stages).empty()) {
      const float white[4] = {1, 1, 1, 1};
      glClearTexImage(target.id(), 0, GL_RGBA, GL_FLOAT, white);
    }
    const Texture *coat = f.get(maybe(kCoat)), *sprite = f.get(maybe(kSketchDepth));
    glProgramUniform1i(program_.id(), program_.uniform("has_coat"), coat != nullptr);
    glProgramUniform1i(program_.id(), program_.uniform("has_sprite"), sprite != nullptr);
    program_.set_params(f.params<StrokePaperParams>());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, strokes_.id());
    // Only where the G-buffer's objects can be: elsewhere every pixel keeps what is under.
    pass_.draw_inside(program_,
                      {{"ids", &f.get(kGBuffer).ids},
                       {"coat", coat ? coat : &none_},
                       {"sprite_depth", sprite ? sprite : &none_},
                       {"paper_height", &height_}},
                      {&target}, f.filter_rect(0), {});
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
