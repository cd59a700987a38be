#include "gpu/sketchy/sketchy_enlarged.hpp"
#include "common/sketchy/sketchy_enlarged.hpp"

#include <glm/gtc/type_ptr.hpp>

#include "common/scene/gbuffer.hpp"
#include "common/sketchy/sketchy.hpp"
#include "gpu/core/stage.hpp"

namespace plumbago::gpu {

namespace {

struct Corner {
  glm::vec3 position, noise_coordinate;
};

std::vector<Corner> triangle_soup(const WorldObject& world, const std::vector<glm::vec3>& coords) {
  std::vector<Corner> soup;
  soup.reserve(world.triangles.size() * 3);
  for (const glm::uvec3& tri : world.triangles)
    for (int k = 0; k < 3; ++k) soup.push_back({world.positions[tri[k]], coords[tri[k]]});
  return soup;
}

}  // namespace

SketchyEnlargedPass::SketchyEnlargedPass(const Scene& enlarged)
    : program_("sketchy/sketchy_enlarged.vert", "sketchy/sketchy_enlarged.frag"), fbo_(make_framebuffer()) {
  std::vector<WorldObject> world = world_geometry(enlarged);
  for (size_t i = 0; i < world.size(); ++i) {
    std::vector<Corner> soup = triangle_soup(world[i], noise_coordinates(*enlarged.objects[i].mesh));
    Batch b{make_buffer(soup.data(), soup.size() * sizeof(Corner)), make_vertex_array(), GLsizei(soup.size())};
    glBindVertexArray(b.layout.id());
    glBindVertexBuffer(0, b.vertices.id(), 0, sizeof(Corner));
    for (GLuint a = 0; a < 2; ++a) {
      glEnableVertexAttribArray(a);
      glVertexAttribFormat(a, 3, GL_FLOAT, GL_FALSE, GLuint(a * sizeof(glm::vec3)));
      glVertexAttribBinding(a, 0);
    }
    glBindVertexArray(0);
    batches_.push_back(std::move(b));
  }
}

void SketchyEnlargedPass::render(const Camera& camera, Texture& out) {
  if (!depth_test_.id()) depth_test_ = make_renderbuffer(out.width, out.height, GL_DEPTH_COMPONENT32F);
  glBindFramebuffer(GL_FRAMEBUFFER, fbo_.id());
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, out.id(), 0);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depth_test_.id());
  GLenum draw = GL_COLOR_ATTACHMENT0;
  glDrawBuffers(1, &draw);
  const float zero[4] = {0, 0, 0, 0}, one = 1;
  glClearBufferfv(GL_COLOR, 0, zero);
  glClearBufferfv(GL_DEPTH, 0, &one);
  glViewport(0, 0, out.width, out.height);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  glUseProgram(program_.id());
  glm::mat4 view = camera.view(), projection = camera.projection(float(out.width) / float(out.height));
  glUniformMatrix4fv(program_.uniform("view"), 1, GL_FALSE, glm::value_ptr(view));
  glUniformMatrix4fv(program_.uniform("projection"), 1, GL_FALSE, glm::value_ptr(projection));
  for (const Batch& b : batches_) {
    glBindVertexArray(b.layout.id());
    glDrawArrays(GL_TRIANGLES, 0, b.corners);
  }
  glBindVertexArray(0);
  glDisable(GL_DEPTH_TEST);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

namespace {

class SketchyEnlargedStagePass : public GpuPass {
 public:
  explicit SketchyEnlargedStagePass(GpuFrame& f) : pass_(enlarged_scene(f.sketchy)) {}
  void run(GpuFrame& f) override { pass_.render(f.scene.camera, f.put(kNoiseCoordinates)); }

 private:
  SketchyEnlargedPass pass_;
};

}  // namespace

PLUMBAGO_GPU_PASS(sketchy_enlarged, {{"sketchy_enlarged"}, {}, make_pass<SketchyEnlargedStagePass>, Probe::Raster});

}  // namespace plumbago::gpu
