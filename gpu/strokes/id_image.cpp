// The ID reference image on the GPU (Kalnins et al. 2002, §4.6), the twin of reference/strokes/id_image.cpp: the
// triangles of common/strokes/id_image.hpp, pulled from a buffer, depth-tested GL_GREATER on
// z = near / d, written as the fragment's depth.
#include "common/strokes/id_image.hpp"

#include "gpu/core/stage.hpp"
#include "gpu/strokes/decal.hpp"

namespace plumbago::gpu {

namespace {

class IdImagePass : public GpuPass {
 public:
  explicit IdImagePass(GpuFrame& f)
      : program_("strokes/id_image.vert", "strokes/id_image.frag"),
        fbo_(make_framebuffer()),
        empty_(make_vertex_array()),
        depth_(make_renderbuffer(f.scene.width, f.scene.height, GL_DEPTH_COMPONENT32F)) {
    // The decals' surface points, projected once for the renderer's frames (Kalnins et al.
    // 2002, §3).
    if (has_decals(f.scene)) decals_ = project_decals_through_gbuffer(f.scene);
  }

  void run(GpuFrame& f) override {
    auto p = f.params<StrokesParams>();
    f.put(kWindowLines, window_lines(f.scene, p, LineObjects::Strokes, &f.get(kLineMeshes),
                                     has_decals(f.scene) ? &decals_ : nullptr));
    std::vector<IdVertex> triangles = id_triangles(f.scene, f.get(kWindowLines), p);
    Texture& target = f.put(kIds);
    glBindFramebuffer(GL_FRAMEBUFFER, fbo_.id());
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, target.id(), 0);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depth_.id());
    const GLuint none[4] = {0, 0, 0, 0};
    const float far = 0;
    glClearBufferuiv(GL_COLOR, 0, none);
    glClearBufferfv(GL_DEPTH, 0, &far);
    if (!triangles.empty()) draw(triangles, target);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
  }

 private:
  void draw(const std::vector<IdVertex>& triangles, const Texture& target) {
    Buffer vertices = make_buffer(triangles.data(), triangles.size() * sizeof(IdVertex));
    glViewport(0, 0, target.width, target.height);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_GREATER);
    glUseProgram(program_.id());
    glProgramUniform2f(program_.id(), program_.uniform("window_size"), float(target.width), float(target.height));
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, vertices.id());
    glBindVertexArray(empty_.id());
    glDrawArrays(GL_TRIANGLES, 0, GLsizei(triangles.size()));
    glDepthFunc(GL_LESS);
    glDisable(GL_DEPTH_TEST);
  }

  Program program_;
  Framebuffer fbo_;
  VertexArray empty_;
  Renderbuffer depth_;
  DecalSurface decals_;
};

}  // namespace

PLUMBAGO_GPU_PASS(id_image, {{"id_image"}, {}, make_pass<IdImagePass>, Probe::Raster});

}  // namespace plumbago::gpu
