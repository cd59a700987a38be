#include "gpu/contour_light.hpp"

namespace plumbago::gpu {

ContourLightPass::ContourLightPass()
    : program_("fullscreen.vert", "contour_light.frag", glsl_params<ContourLightParams>()) {
  glProgramUniform1i(program_.id(), program_.uniform("contour_darkness"), 0);
  glProgramUniform1i(program_.id(), program_.uniform("normals"), 1);
}

void ContourLightPass::run(const Texture& contour_darkness, const GBufferTargets& g,
                           const std::vector<Light>& view_lights, const ContourLightParams& p, Texture& out) {
  program_.set_params(p);
  set_lights(program_, view_lights);
  pass_.draw(program_, {&contour_darkness, &g.normal}, out);
}

}  // namespace plumbago::gpu
