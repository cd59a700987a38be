#include "gpu/interior_intensity.hpp"

#include <stdexcept>

namespace plumbago::gpu {

void set_lights(const Program& program, const std::vector<Light>& lights) {
  constexpr size_t kMaxLights = 8;  // MAX_LIGHTS in shaders/common_lights.glsl
  if (lights.size() > kMaxLights)
    throw std::invalid_argument("the GPU backend shades with at most 8 lights, the scene has " +
                                std::to_string(lights.size()));
  std::vector<glm::vec3> directions;
  std::vector<float> intensities;
  for (const Light& l : lights) {
    directions.push_back(l.direction);
    intensities.push_back(l.intensity);
  }
  GLuint id = program.id();
  glProgramUniform1i(id, program.uniform("light_count"), GLint(lights.size()));
  if (lights.empty()) return;
  glProgramUniform3fv(id, program.uniform("light_direction"), GLsizei(lights.size()), &directions[0].x);
  glProgramUniform1fv(id, program.uniform("light_intensity"), GLsizei(lights.size()), intensities.data());
}

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
