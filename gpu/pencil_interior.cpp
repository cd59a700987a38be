#include "gpu/pencil_interior.hpp"

namespace plumbago::gpu {

PencilInteriorPass::PencilInteriorPass()
    : program_("fullscreen.vert", "pencil_interior.frag", glsl_params<InteriorParams>()) {
  const char* samplers[] = {"interior_intensity", "bary", "theta_min", "theta_max", "ids", "pencil_stack", "paper_normal"};
  for (int i = 0; i < 7; ++i) glProgramUniform1i(program_.id(), program_.uniform(samplers[i]), i);
}

void PencilInteriorPass::run(const GBufferTargets& g, const Texture& intensity, const Texture& stack,
                             const Texture& paper_normal, const InteriorOptions& o, const InteriorParams& p,
                             float mu_p, Texture& out) {
  program_.set_params(p);
  glProgramUniform1i(program_.id(), program_.uniform("crosshatch"), o.crosshatch);
  glProgramUniform1i(program_.id(), program_.uniform("paper_effect"), o.paper);
  glProgramUniform1f(program_.id(), program_.uniform("mu_p"), mu_p);
  pass_.draw(program_, {&intensity, &g.bary, &g.theta_min, &g.theta_max, &g.ids, &stack, &paper_normal}, out);
}

}  // namespace plumbago::gpu
