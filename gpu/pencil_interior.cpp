#include "gpu/pencil_interior.hpp"

namespace plumbago::gpu {

PencilInteriorPass::PencilInteriorPass()
    : program_("fullscreen.vert", "pencil_interior.frag", glsl_params<InteriorParams>()) {
  const char* samplers[] = {"normals", "bary", "theta_min", "theta_max", "ids", "pencil_stack", "paper_normal"};
  for (int i = 0; i < 7; ++i) glProgramUniform1i(program_.id(), program_.uniform(samplers[i]), i);
}

void PencilInteriorPass::run(const GBufferTargets& g, const std::vector<Light>& view_lights, const Texture& stack,
                             const Texture& paper_normal, const InteriorOptions& o, const InteriorParams& p,
                             float mu_p, Texture& darkness, Texture& intensity, const PixelRect& covered) {
  program_.set_params(p);
  set_lights(program_, view_lights);
  glProgramUniform1i(program_.id(), program_.uniform("crosshatch"), o.crosshatch);
  glProgramUniform1i(program_.id(), program_.uniform("paper_effect"), o.paper);
  glProgramUniform1f(program_.id(), program_.uniform("mu_p"), mu_p);
  pass_.draw_inside(program_, {&g.normal, &g.bary, &g.theta_min, &g.theta_max, &g.ids, &stack, &paper_normal},
                    {&darkness, &intensity}, covered, {glm::vec4(0.0f), glm::vec4(1.0f)});
}

}  // namespace plumbago::gpu
