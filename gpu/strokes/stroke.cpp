// The stroke raster on the GPU (Kalnins et al. 2002, §4.1), the twin of reference/strokes/stroke.cpp: the
// runs' polylines, styles and samples made on the GPU from the runs the visibility steps left
// there (gpu/strokes/stroke_samples.hpp, gpu/strokes/window_paths.hpp, gpu/strokes/run_styles.hpp),
// their ribbons expanded in the vertex
// shader (shaders/strokes/common_ribbon.glsl) and drawn in one indirect call, blended premultiplied
// "over" onto the page.
#include "gpu/strokes/stroke.hpp"

#include <optional>

#include "common/strokes/stroke_paper.hpp"
#include "gpu/core/stage.hpp"
#include "gpu/strokes/brush_parameters.hpp"
#include "gpu/strokes/stroke_samples.hpp"

namespace plumbago::gpu {

namespace {

class StrokePass : public GpuPass {
 public:
  explicit StrokePass(GpuFrame& f)
      : program_("strokes/stroke.vert", "strokes/stroke.frag", glsl_params<StrokePaperParams>()),
        textures_(upload_texture_3d(stroke_texture_layers(f.scene.seed), GL_R32F, GL_TEXTURE_2D_ARRAY)),
        height_(upload_texture(f.get(kPaperHeight), GL_R32F)),
        fbo_(make_framebuffer()),
        empty_(make_vertex_array()) {
    set_sampling(textures_, GL_LINEAR, GL_REPEAT, GL_CLAMP_TO_EDGE);
  }

  void run(GpuFrame& f) override {
    const WindowLines& lines = f.get(kWindowLines);
    const RunTables* tables = f.get(maybe(kRunTables));
    std::optional<UploadedRuns> uploaded;  // where visibility ran elsewhere
    if (!tables) tables = &uploaded.emplace(lines, f.get(kVisibleRuns)).tables();
    if (!styles_ || styles_->decal_count() != lines.decal_styles.size())
      styles_.emplace(f.scene.strokes, lines.decal_styles);  // the scene's: made once
    // Coherent: the fit's brush paths, else (a still frame's fit is withheld) new ones.
    const bool coherent = strokes_coherent(f.scene.params);
    const BrushFit* fit = coherent && f.ran("brush_parameters") ? f.get(maybe(kBrushFit)) : nullptr;
    samples_(*tables, *styles_, f.scene.seed, fit, coherent);
    Texture& target = f.put(kStrokeColor);
    if (drawn_over(find_output(kStrokeColor.name), f.stages).empty()) copy_page(f.get(kPage), target);
    if (!samples_.draw()) return;
    program_.set_params(f.params<StrokePaperParams>());
    glProgramUniform2f(program_.id(), program_.uniform("window_size"), float(target.width), float(target.height));
    glBindFramebuffer(GL_FRAMEBUFFER, fbo_.id());
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, target.id(), 0);
    glViewport(0, 0, target.width, target.height);
    glEnable(GL_BLEND);
    glBlendFunc(GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
    bind_textures(program_, {{"stroke_textures", &textures_}, {"paper_height", &height_}});
    glUseProgram(program_.id());
    samples_.bind();
    glBindVertexArray(empty_.id());
    glBindBuffer(GL_DRAW_INDIRECT_BUFFER, samples_.draw()->id());
    glDrawArraysIndirect(GL_TRIANGLES, nullptr);
    glBindBuffer(GL_DRAW_INDIRECT_BUFFER, 0);
    glDisable(GL_BLEND);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
  }

 private:
  // Where the page was made outside this frame (parity feeds it), the strokes draw on a copy.
  static void copy_page(const Texture& page, const Texture& target) {
    glCopyImageSubData(page.id(), GL_TEXTURE_2D, 0, 0, 0, 0, target.id(), GL_TEXTURE_2D, 0, 0, 0, 0, page.width,
                       page.height, 1);
  }

  std::optional<RunStyleTables> styles_;
  StrokeSamples samples_;
  Program program_;
  Texture textures_, height_;
  Framebuffer fbo_;
  VertexArray empty_;
};

}  // namespace

PLUMBAGO_GPU_PASS(stroke, {{"stroke"}, {}, make_pass<StrokePass>, Probe::Raster});

}  // namespace plumbago::gpu
