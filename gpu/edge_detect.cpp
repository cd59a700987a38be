#include "gpu/edge_detect.hpp"

namespace plumbago::gpu {

EdgeDetectPass::EdgeDetectPass()
    : program_("fullscreen.vert", "edge_detect.frag", glsl_params<EdgeDetectParams>() + glsl_params<ContourLightParams>()) {
  glProgramUniform1i(program_.id(), program_.uniform("normals"), 0);
  glProgramUniform1i(program_.id(), program_.uniform("shading_normals"), 1);
}

void EdgeDetectPass::run(const GBufferTargets& g, const EdgeDetectParams& p, const std::vector<Light>& view_lights,
                         const ContourLightParams& light, Texture& darkness, Texture& lit, const PixelRect& covered) {
  program_.set_params(p);
  program_.set_params(light);
  set_lights(program_, view_lights);
  glProgramUniform1f(program_.id(), program_.uniform("near_plane"), g.near);
  glProgramUniform1f(program_.id(), program_.uniform("far_plane"), g.far);
  const Texture& normals = p.normals == EdgeNormals::Face ? g.face_normal : g.normal;
  glm::vec4 outside(background_darkness(p));  // unlit: a background normal gets no light
  pass_.draw_inside(program_, {&normals, &g.normal}, {&darkness, &lit}, covered, {outside, outside});
}

}  // namespace plumbago::gpu
