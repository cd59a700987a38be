#include "gpu/pencil_interior.hpp"

namespace plumbago::gpu {

PencilInteriorPass::PencilInteriorPass()
    : programs_("fullscreen.vert", "pencil_interior.frag", glsl_params<InteriorParams>(),
                {"PHONG", "NEAREST_CORNER", "CROSSHATCH", "PAPER_EFFECT", "WRITE_INTENSITY"}) {}

// The choices that decide which code runs are compiled in (shaders/pencil_interior.frag).
const Program& PencilInteriorPass::program_for(const InteriorOptions& o, const InteriorParams& p, bool writes_intensity) {
  return programs_.get({p.shading == InteriorShading::Phong, p.blend == InteriorBlend::NearestCorner, o.crosshatch, o.paper,
                        writes_intensity},
                       [](const Program& made) {
                         const char* samplers[] = {"normals", "bary", "ids", "pencil_stack", "paper_normal"};
                         for (int i = 0; i < 5; ++i) glProgramUniform1i(made.id(), made.uniform(samplers[i]), i);
                       });
}

void PencilInteriorPass::run(const GBufferTargets& g, const TriangleAngles& angles, const std::vector<Light>& view_lights, const Texture& stack,
                             const Texture& paper_normal, const InteriorOptions& o, const InteriorParams& p,
                             float mu_p, Texture& darkness, Texture* intensity, const PixelRect& covered) {
  const Program& program = program_for(o, p, intensity != nullptr);
  program.set_params(p);
  set_lights(program, view_lights);
  glProgramUniform1f(program.id(), program.uniform("mu_p"), mu_p);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, angles.angles.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, angles.first_triangle.id());
  std::initializer_list<const Texture*> textures = {&g.normal, &g.bary, &g.ids, &stack, &paper_normal};
  if (intensity)
    pass_.draw_inside(program, textures, {&darkness, intensity}, covered, {glm::vec4(0.0f), glm::vec4(1.0f)});
  else
    pass_.draw_inside(program, textures, {&darkness}, covered, {glm::vec4(0.0f)});
}

}  // namespace plumbago::gpu
