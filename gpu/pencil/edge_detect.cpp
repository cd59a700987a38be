#include "gpu/pencil/edge_detect.hpp"

#include "common/scene/lights.hpp"
#include "gpu/core/stage.hpp"
#include "gpu/pencil/contour_blocks.hpp"

namespace plumbago::gpu {

EdgeDetectPass::EdgeDetectPass()
    : programs_("util/fullscreen.vert", "pencil/edge_detect.frag",
                glsl_params<EdgeDetectParams>() + glsl_params<ContourLightParams>() + contour_block_define(),
                {"WRITE_UNLIT", "MARK_CONTOUR_BLOCKS"}) {}

void EdgeDetectPass::run(const GBufferTargets& g, const EdgeDetectParams& p, const std::vector<Light>& view_lights,
                         const ContourLightParams& light, const EdgeOutputs& out, const PixelRect& covered) {
  const Program& program = programs_.get({out.darkness != nullptr, out.block_marks != nullptr});
  program.set_params(p);
  program.set_params(light);
  set_lights(program, view_lights);
  glProgramUniform1f(program.id(), program.uniform("near_plane"), g.near);
  glProgramUniform1f(program.id(), program.uniform("far_plane"), g.far);
  const Texture& normals = p.normals == EdgeNormals::Face ? g.face_normal : g.normal;
  float background = background_darkness(p);  // unlit: a background normal gets no light
  if (out.block_marks) {
    float mark = background > 0.0f ? 1.0f : 0.0f;  // the blocks outside `covered`
    glClearTexImage(out.block_marks->id(), 0, GL_RED, GL_FLOAT, &mark);
    glBindImageTexture(0, out.block_marks->id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_R32F);
  }
  glm::vec4 outside(background);
  if (out.darkness)
    pass_.draw_inside(program, {{"normals", &normals}, {"shading_normals", &g.normal}}, {&out.lit, out.darkness},
                      covered, {outside, outside});
  else
    pass_.draw_inside(program, {{"normals", &normals}, {"shading_normals", &g.normal}}, {&out.lit}, covered, {outside});
}

namespace {

// Edge detection and contour lighting as a frame draws them: a frame writes only d'; the
// blocks' marks when multiple contours are drawn (shared as kContourBlockMarks).
class EdgeAndLightPass : public GpuPass {
 public:
  explicit EdgeAndLightPass(GpuFrame& f) {
    f.read_near_objects(kGBuffer, 2);  // the filter runs within 1 pixel and reads 1 more
    if (f.ran("multi_contour")) {
      marks_ = make_contour_block_marks(f.scene.width, f.scene.height);
      f.put(kContourBlockMarks, marks_);
    }
  }
  void run(GpuFrame& f) override {
    pass_.run(
        f.get(kGBuffer), f.params<EdgeDetectParams>(), view_space_lights(f.scene), f.params<ContourLightParams>(),
        {f.put(kLitContourDarkness), f.dump ? &f.put(kContourDarkness) : nullptr, marks_.id() ? &marks_ : nullptr},
        f.filter_rect(1));
  }

 private:
  EdgeDetectPass pass_;
  Texture marks_;
};

}  // namespace

PLUMBAGO_GPU_PASS(edge_detect, {{"edge_detect", "contour_light"},
                                {kContourDarkness.name},
                                make_pass<EdgeAndLightPass>,
                                Probe::Fetch3x3});

}  // namespace plumbago::gpu
