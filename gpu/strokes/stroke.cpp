// The stroke raster on the GPU (Kalnins et al. 2002, §4.1), the twin of reference/strokes/stroke.cpp: the
// runs' samples uploaded, their ribbons expanded in the vertex shader (shaders/strokes/common_ribbon.glsl)
// and drawn in one call, blended premultiplied "over" onto the page.
#include "gpu/strokes/stroke.hpp"

#include <algorithm>
#include <cstdint>

#include "common/strokes/stroke_paper.hpp"
#include "gpu/core/stage.hpp"

namespace plumbago::gpu {

namespace {

// A run's samples appended as records, with the run's own record.
void append(const RunStroke& stroke, std::vector<SampleRecord>& samples, std::vector<RunRecord>& runs) {
  const std::vector<StrokeSample>& q = stroke.samples.samples;
  if (q.size() < 2) return;
  const StrokeStyle& style = stroke.style;
  bool whole = std::all_of(q.begin(), q.end() - 1, [](const StrokeSample& x) { return x.pen_down_after; });
  auto run = uint32_t(runs.size());
  runs.push_back({glm::vec4(style.color_r, style.color_g, style.color_b, float(int(style.texture))),
                  uint32_t(samples.size()), uint32_t(q.size()), stroke.samples.closed && whole});
  for (const StrokeSample& x : q)
    samples.push_back({glm::vec2(x.position), float(x.s / style.texture_period_px), float(x.width), float(x.alpha), run,
                       x.pen_down_after});
}

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
    RibbonBuffers ribbons(run_strokes(f.get(kWindowLines), f.get(kVisibleRuns), f.scene.strokes, f.scene.seed));
    Texture& target = f.put(kStrokeColor);
    if (drawn_over(find_output(kStrokeColor.name), f.stages).empty()) copy_page(f.get(kPage), target);
    if (ribbons.vertices() == 0) return;
    program_.set_params(f.params<StrokePaperParams>());
    glProgramUniform2f(program_.id(), program_.uniform("window_size"), float(target.width), float(target.height));
    glBindFramebuffer(GL_FRAMEBUFFER, fbo_.id());
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, target.id(), 0);
    glViewport(0, 0, target.width, target.height);
    glEnable(GL_BLEND);
    glBlendFunc(GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
    bind_textures(program_, {{"stroke_textures", &textures_}, {"paper_height", &height_}});
    glUseProgram(program_.id());
    ribbons.bind();
    glBindVertexArray(empty_.id());
    glDrawArrays(GL_TRIANGLES, 0, ribbons.vertices());
    glDisable(GL_BLEND);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
  }

 private:
  // Where the page was made outside this frame (parity feeds it), the strokes draw on a copy.
  static void copy_page(const Texture& page, const Texture& target) {
    glCopyImageSubData(page.id(), GL_TEXTURE_2D, 0, 0, 0, 0, target.id(), GL_TEXTURE_2D, 0, 0, 0, 0, page.width,
                       page.height, 1);
  }

  Program program_;
  Texture textures_, height_;
  Framebuffer fbo_;
  VertexArray empty_;
};

}  // namespace

RibbonBuffers::RibbonBuffers(const std::vector<RunStroke>& strokes) {
  std::vector<SampleRecord> samples;
  std::vector<RunRecord> runs;
  for (const RunStroke& stroke : strokes) append(stroke, samples, runs);
  vertices_ = GLsizei(6 * samples.size());
  if (samples.empty()) return;
  samples_ = make_buffer(samples.data(), samples.size() * sizeof(SampleRecord));
  runs_ = make_buffer(runs.data(), runs.size() * sizeof(RunRecord));
}

void RibbonBuffers::bind() const {
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, samples_.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, runs_.id());
}

PLUMBAGO_GPU_PASS(stroke, {{"stroke"}, {}, make_pass<StrokePass>, Probe::Raster});

}  // namespace plumbago::gpu
