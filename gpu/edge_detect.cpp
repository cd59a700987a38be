#include "gpu/edge_detect.hpp"

namespace plumbago::gpu {

EdgeDetectPass::EdgeDetectPass() : program_("fullscreen.vert", "edge_detect.frag", glsl_params<EdgeDetectParams>()) {
  glProgramUniform1i(program_.id(), program_.uniform("normals"), 0);
  glProgramUniform1i(program_.id(), program_.uniform("depth"), 1);
}

void EdgeDetectPass::run(const GBufferTargets& g, const EdgeDetectParams& p, Texture& out) {
  program_.set_params(p);
  glProgramUniform1f(program_.id(), program_.uniform("near_plane"), g.near);
  glProgramUniform1f(program_.id(), program_.uniform("far_plane"), g.far);
  const Texture& normals = p.normals == EdgeNormals::Face ? g.face_normal : g.normal;
  pass_.draw(program_, {&normals, &g.depth}, out);
}

}  // namespace plumbago::gpu
