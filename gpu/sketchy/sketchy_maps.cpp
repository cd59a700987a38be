#include "gpu/sketchy/sketchy_maps.hpp"

#include "common/sketchy/sketchy.hpp"
#include "common/sketchy/sketchy_maps.hpp"
#include "gpu/core/stage.hpp"

namespace plumbago::gpu {

namespace {

Texture color_table(const std::vector<glm::vec3>& colors) {
  Image table(std::max<int>(1, int(colors.size())), 1, 3);
  for (size_t k = 0; k < colors.size(); ++k)
    for (int c = 0; c < 3; ++c) table.at(int(k), 0, c) = colors[k][c];
  return upload_texture(table, GL_RGBA32F);
}

}  // namespace

SketchyMapsPass::SketchyMapsPass(const std::vector<glm::vec3>& colors)
    : program_("util/fullscreen.vert", "sketchy/sketchy_maps.frag", glsl_params<EdgeDetectParams>()),
      colors_(color_table(colors)) {}

void SketchyMapsPass::run(const GBufferTargets& g, const EdgeDetectParams& p, Texture& edge, Texture& shade,
                          const PixelRect& covered) {
  program_.set_params(p);
  glProgramUniform1f(program_.id(), program_.uniform("near_plane"), g.near);
  glProgramUniform1f(program_.id(), program_.uniform("far_plane"), g.far);
  const Texture& normals = p.normals == EdgeNormals::Face ? g.face_normal : g.normal;
  // Background pixels: their d, edge depth = far, no shade.
  pass_.draw_inside(program_, {{"normals", &normals}, {"ids", &g.ids}, {"colors", &colors_}}, {&edge, &shade}, covered,
                    {glm::vec4(background_darkness(p), g.far, 0, 0), glm::vec4(0)});
}

namespace {

class SketchyMapsStagePass : public GpuPass {
 public:
  explicit SketchyMapsStagePass(GpuFrame& f) : pass_(object_colors(f.sketchy)) {
    f.read_region(kSketchyGBuffer, {0, 0, f.scene.width, f.scene.height});
  }
  void run(GpuFrame& f) override {
    pass_.run(f.get(kSketchyGBuffer), f.params<EdgeDetectParams>(), f.put(kSketchyEdge), f.put(kSketchyShade),
              filter_rect(f.sketchy, 1));
  }

 private:
  SketchyMapsPass pass_;
};

}  // namespace

PLUMBAGO_GPU_PASS(sketchy_maps, {{"sketchy_maps"}, {}, make_pass<SketchyMapsStagePass>, Probe::Fetch3x3});

}  // namespace plumbago::gpu
