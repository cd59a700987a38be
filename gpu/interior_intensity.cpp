#include "gpu/interior_intensity.hpp"

namespace plumbago::gpu {

InteriorIntensityPass::InteriorIntensityPass()
    : program_("fullscreen.vert", "interior_intensity.frag", glsl_params<InteriorParams>()) {
  glProgramUniform1i(program_.id(), program_.uniform("gouraud"), 0);
  glProgramUniform1i(program_.id(), program_.uniform("normals"), 1);
  glProgramUniform1i(program_.id(), program_.uniform("ids"), 2);
}

void InteriorIntensityPass::run(const GBufferTargets& g, const std::vector<Light>& view_lights,
                                const InteriorParams& p, Texture& out) {
  program_.set_params(p);
  set_lights(program_, view_lights);
  pass_.draw(program_, {&g.gouraud, &g.normal, &g.ids}, out);
}

}  // namespace plumbago::gpu
