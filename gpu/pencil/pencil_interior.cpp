#include "gpu/pencil/pencil_interior.hpp"

#include "common/pencil/paper.hpp"
#include "common/scene/lights.hpp"
#include "gpu/core/stage.hpp"

namespace plumbago::gpu {

PencilInteriorPass::PencilInteriorPass()
    : programs_("util/fullscreen.vert", "pencil/pencil_interior.frag", glsl_params<InteriorParams>(),
                {"PHONG", "NEAREST_CORNER", "CROSSHATCH", "PAPER_EFFECT", "WRITE_INTENSITY"}) {}

// The choices that decide which code runs are compiled in (shaders/pencil/pencil_interior.frag).
const Program& PencilInteriorPass::program_for(const InteriorOptions& o, const InteriorParams& p,
                                               bool writes_intensity) {
  return programs_.get({p.shading == InteriorShading::Phong, p.blend == InteriorBlend::NearestCorner, o.crosshatch,
                        o.paper, writes_intensity});
}

void PencilInteriorPass::run(const PencilInteriorInputs& in, const InteriorParams& p, float mu_p,
                             const PencilInteriorOutputs& out, const PixelRect& covered) {
  const Program& program = program_for(in.options, p, out.intensity != nullptr);
  program.set_params(p);
  set_lights(program, in.view_lights);
  glProgramUniform1f(program.id(), program.uniform("mu_p"), mu_p);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, in.angles.angles.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, in.angles.first_triangle.id());
  const GBufferTargets& g = in.gbuffer;
  std::initializer_list<TextureBinding> textures = {{"normals", &g.normal},
                                                    {"bary", &g.bary},
                                                    {"ids", &g.ids},
                                                    {"pencil_stack", &in.stack},
                                                    {"paper_normal", &in.paper_normal}};
  if (out.intensity)
    pass_.draw_inside(program, textures, {&out.darkness, out.intensity}, covered, {glm::vec4(0.0f), glm::vec4(1.0f)});
  else
    pass_.draw_inside(program, textures, {&out.darkness}, covered, {glm::vec4(0.0f)});
}

namespace {

// Interior intensity and pencil shading as a frame draws them: a frame writes only D_i.
class InteriorPass : public GpuPass {
 public:
  explicit InteriorPass(GpuFrame& f)
      : stack_(upload_texture_3d(f.get(kPencilStack), GL_R32F)),
        paper_normal_(f.get(maybe(kPaperNormal)) ? upload_texture(f.get(kPaperNormal), GL_RGBA32F)
                                                 : make_texture(1, 1, GL_RGBA32F)) {
    f.read_near_objects(kGBuffer, 0);
  }
  void run(GpuFrame& f) override {
    std::vector<Light> lights = view_space_lights(f.scene);
    pass_.run(
        {f.get(kGBuffer), f.get(kTriangleAngles), lights, stack_, paper_normal_, interior_options(f.scene.effects)},
        f.params<InteriorParams>(), f.params<PaperParams>().mu_p,
        {f.put(kInteriorDarkness), f.dump ? &f.put(kIntensity) : nullptr}, f.filter_rect(0));
  }

 private:
  PencilInteriorPass pass_;
  Texture stack_, paper_normal_;
};

}  // namespace

PLUMBAGO_GPU_PASS(pencil_interior,
                  {{"interior_intensity", "pencil_interior"}, {kIntensity.name}, make_pass<InteriorPass>});

}  // namespace plumbago::gpu
