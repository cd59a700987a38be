#include "gpu/pencil_interior.hpp"

namespace plumbago::gpu {

// One program per combination of the choices that decide which code runs, compiled in
// (shaders/pencil_interior.frag says why), made on first use.
const Program& PencilInteriorPass::program_for(const InteriorOptions& o, const InteriorParams& p) {
  const bool flags[] = {p.shading == InteriorShading::Phong, p.blend == InteriorBlend::NearestCorner, o.crosshatch, o.paper};
  const char* names[] = {"PHONG", "NEAREST_CORNER", "CROSSHATCH", "PAPER_EFFECT"};
  int key = 0;
  std::string defines;
  for (int k = 0; k < 4; ++k) {
    key |= int(flags[k]) << k;
    defines += "#define " + std::string(names[k]) + (flags[k] ? " 1\n" : " 0\n");
  }
  auto it = programs_.find(key);
  if (it == programs_.end()) {
    it = programs_.emplace(key, Program("fullscreen.vert", "pencil_interior.frag", glsl_params<InteriorParams>() + defines)).first;
    const char* samplers[] = {"normals", "bary", "theta_min", "theta_max", "ids", "pencil_stack", "paper_normal"};
    for (int i = 0; i < 7; ++i) glProgramUniform1i(it->second.id(), it->second.uniform(samplers[i]), i);
  }
  return it->second;
}

void PencilInteriorPass::run(const GBufferTargets& g, const std::vector<Light>& view_lights, const Texture& stack,
                             const Texture& paper_normal, const InteriorOptions& o, const InteriorParams& p,
                             float mu_p, Texture& darkness, Texture& intensity, const PixelRect& covered) {
  const Program& program = program_for(o, p);
  program.set_params(p);
  set_lights(program, view_lights);
  glProgramUniform1f(program.id(), program.uniform("mu_p"), mu_p);
  pass_.draw_inside(program, {&g.normal, &g.bary, &g.theta_min, &g.theta_max, &g.ids, &stack, &paper_normal},
                    {&darkness, &intensity}, covered, {glm::vec4(0.0f), glm::vec4(1.0f)});
}

}  // namespace plumbago::gpu
