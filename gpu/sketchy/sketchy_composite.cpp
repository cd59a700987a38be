#include "gpu/sketchy/sketchy_composite.hpp"

#include "common/sketchy/sketchy_composite.hpp"
#include "gpu/core/stage.hpp"

#include <algorithm>

#include <glm/gtc/type_ptr.hpp>

namespace plumbago::gpu {

namespace {

constexpr int kMaxCopies = 8;  // copy_matrices[8] in sketchy_composite.frag; sketchy.edge_copies <= 8

Texture repeating(Texture t, GLenum filter) {
  set_sampling(t, filter, GL_REPEAT, GL_REPEAT, GL_REPEAT);
  return t;
}

}  // namespace

SketchyNoiseTextures upload_sketchy_noise(const SketchyNoise& n) {
  Image none(1, 1, 1);
  return {
      repeating(upload_texture(n.perlin.empty() ? none : n.perlin, GL_R32F), GL_LINEAR),
      repeating(upload_texture(n.white.empty() ? none : n.white, GL_RG32F), GL_NEAREST),
      repeating(upload_texture_3d(n.perlin_3d.empty() ? std::vector<Image>{none} : n.perlin_3d, GL_R32F), GL_LINEAR)};
}

SketchyCompositePass::SketchyCompositePass()
    : program_("util/fullscreen.vert", "sketchy/sketchy_composite.frag", glsl_params<SketchyParams>()),
      fbo_(make_framebuffer()),
      empty_(make_vertex_array()) {}

void SketchyCompositePass::set_uniforms(const SketchyCompositeInputs& in, const SketchyParams& p) {
  GLuint id = program_.id();
  program_.set_params(p);
  glProgramUniform1f(id, program_.uniform("near_plane"), in.gbuffer.near);
  glProgramUniform1f(id, program_.uniform("far_plane"), in.gbuffer.far);
  glm::mat2 shade = shade_matrix(p);
  glProgramUniformMatrix2fv(id, program_.uniform("shade_matrix"), 1, GL_FALSE, glm::value_ptr(shade));
  glm::mat2 matrices[kMaxCopies];
  glm::vec3 inks[kMaxCopies];
  glm::vec2 shifts[kMaxCopies];
  for (int k = 0; k < kMaxCopies; ++k)
    matrices[k] = copy_matrix(p, k), inks[k] = copy_ink(p, k), shifts[k] = copy_noise_shift(k);
  glProgramUniformMatrix2fv(id, program_.uniform("copy_matrices[0]"), kMaxCopies, GL_FALSE,
                            glm::value_ptr(matrices[0]));
  glProgramUniform3fv(id, program_.uniform("copy_inks[0]"), kMaxCopies, glm::value_ptr(inks[0]));
  glProgramUniform2fv(id, program_.uniform("copy_shifts[0]"), kMaxCopies, glm::value_ptr(shifts[0]));
}

void SketchyCompositePass::run(const SketchyCompositeInputs& in, const SketchyParams& p, Texture& color, bool on_paper,
                               const Renderbuffer* under_depth, Texture& sprite_depth, const PixelRect& reach) {
  set_uniforms(in, p);
  set_sampling(in.edge_map, GL_LINEAR, GL_CLAMP_TO_EDGE, GL_CLAMP_TO_EDGE);  // darkness is read filtered
  if (!under_depth && !own_depth_.id())
    own_depth_ = make_renderbuffer(color.width, color.height, GL_DEPTH_COMPONENT32F);
  glBindFramebuffer(GL_FRAMEBUFFER, fbo_.id());
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, color.id(), 0);
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT1, GL_TEXTURE_2D, sprite_depth.id(), 0);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER,
                            under_depth ? under_depth->id() : own_depth_.id());
  const GLenum draw[2] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1};
  glDrawBuffers(2, draw);
  const float white[4] = {1, 1, 1, 1}, one = 1;
  glClearBufferfv(GL_COLOR, 1, white);
  if (on_paper) glClearBufferfv(GL_COLOR, 0, white);
  if (!under_depth) glClearBufferfv(GL_DEPTH, 0, &one);
  glViewport(0, 0, color.width, color.height);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  bind_textures(program_, {{"edge_map", &in.edge_map},
                           {"shade_map", &in.shade_map},
                           {"depth", &in.gbuffer.depth},
                           {"noise", &in.noise.perlin},
                           {"white_noise", &in.noise.white},
                           {"noise_3d", &in.noise.perlin_3d},
                           {"noise_coordinates", &in.noise_coordinates}});
  glUseProgram(program_.id());
  glBindVertexArray(empty_.id());
  glEnable(GL_SCISSOR_TEST);
  glScissor(reach.x0, reach.y0, std::max(0, reach.x1 - reach.x0), std::max(0, reach.y1 - reach.y0));
  glDrawArrays(GL_TRIANGLES, 0, 3);
  glDisable(GL_SCISSOR_TEST);
  glBindVertexArray(0);
  glDisable(GL_DEPTH_TEST);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, 0);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

namespace {

// The sketch over what the pencil pipeline drew (its color target), or over white paper where
// it did not run; tested against the ordinary objects' depth buffer wherever the G-buffer ran
// (the pencil pipeline's or the strokes').
class SketchyCompositeStagePass : public GpuPass {
 public:
  explicit SketchyCompositeStagePass(GpuFrame& f)
      : noise_(upload_sketchy_noise(f.get(kSketchyNoise))), none_(make_texture(1, 1, GL_RGBA32F)) {
    f.read_region(kSketchyGBuffer, {0, 0, f.scene.width, f.scene.height});  // depth at the uncertainty's offsets
  }
  void run(GpuFrame& f) override {
    const Texture* coordinates = f.get(maybe(kNoiseCoordinates));
    pass_.run(
        {f.get(kSketchyEdge), f.get(kSketchyShade), f.get(kSketchyGBuffer), noise_, coordinates ? *coordinates : none_},
        f.params<SketchyParams>(), f.put(kSketchColor), drawn_over(find_output(kSketchColor.name), f.stages).empty(),
        f.get(maybe(kDepthBuffer)), f.put(kSketchDepth), composite_rect(f.sketchy, f.scene.width, f.scene.height));
  }

 private:
  SketchyCompositePass pass_;
  SketchyNoiseTextures noise_;
  Texture none_;
};

}  // namespace

PLUMBAGO_GPU_PASS(sketchy_composite,
                  {{"sketchy_composite"}, {}, make_pass<SketchyCompositeStagePass>, Probe::Fetch3x3});

}  // namespace plumbago::gpu
