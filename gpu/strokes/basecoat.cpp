// Base coat on the GPU (Kalnins et al. 2002, §4.2), the twin of reference/strokes/basecoat.cpp: a full-window pass
// over the G-buffer's ids and barycentrics, with the corners' s as one record per triangle.
#include "common/strokes/basecoat.hpp"

#include "gpu/core/stage.hpp"
#include "gpu/gl/framebuffer.hpp"

namespace plumbago::gpu {

namespace {

class BaseCoatPass : public GpuPass {
 public:
  explicit BaseCoatPass(GpuFrame& f)
      : program_("util/fullscreen.vert", "strokes/basecoat.frag", glsl_params<BaseCoatParams>()) {
    auto p = f.params<BaseCoatParams>();
    shade(f);
    texture_ = upload_texture(basecoat_texture(p), GL_RGBA32F);
    set_sampling(texture_, GL_LINEAR, GL_CLAMP_TO_EDGE, GL_CLAMP_TO_EDGE);
    f.read_near_objects(kGBuffer, 0);
  }
  void moved(GpuFrame& f, bool lights_moved) override {
    if (lights_moved) shade(f);
  }
  void run(GpuFrame& f) override {
    const GBufferTargets& g = f.get(kGBuffer);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, corners_.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, first_.id());
    // Only the objects' rectangle runs the shader; outside it the coat is transparent.
    pass_.draw_inside(program_, {{"ids", &g.ids}, {"bary", &g.bary}, {"coat", &texture_}}, {&f.put(kCoat)},
                      f.filter_rect(0), {glm::vec4(0.0f)});
  }

 private:
  // The corners' shades under the frame's lights.
  void shade(const GpuFrame& f) {
    TriangleShades shades = triangle_shades(f.ordinary, f.params<BaseCoatParams>());
    if (shades.corners.empty()) shades.corners.push_back(glm::vec4(0.0f));
    if (shades.first_triangle.empty()) shades.first_triangle.push_back(0);
    corners_ = make_buffer(shades.corners.data(), shades.corners.size() * sizeof(glm::vec4));
    first_ = make_buffer(shades.first_triangle.data(), shades.first_triangle.size() * sizeof(uint32_t));
  }

  Program program_;
  FullscreenPass pass_;
  Buffer corners_, first_;
  Texture texture_;
};

}  // namespace

PLUMBAGO_GPU_PASS(basecoat, {{"basecoat"}, {}, make_pass<BaseCoatPass>});

}  // namespace plumbago::gpu
