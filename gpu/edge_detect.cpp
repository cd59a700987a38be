#include "gpu/edge_detect.hpp"

#include "gpu/multi_contour.hpp"

namespace plumbago::gpu {

EdgeDetectPass::EdgeDetectPass()
    : programs_("fullscreen.vert", "edge_detect.frag",
                glsl_params<EdgeDetectParams>() + glsl_params<ContourLightParams>() + contour_block_define(),
                {"WRITE_UNLIT", "MARK_CONTOUR_BLOCKS"}) {}

void EdgeDetectPass::run(const GBufferTargets& g, const EdgeDetectParams& p, const std::vector<Light>& view_lights,
                         const ContourLightParams& light, const EdgeOutputs& out, const PixelRect& covered) {
  const Program& program = programs_.get({out.darkness != nullptr, out.block_marks != nullptr}, [](const Program& made) {
    glProgramUniform1i(made.id(), made.uniform("normals"), 0);
    glProgramUniform1i(made.id(), made.uniform("shading_normals"), 1);
  });
  program.set_params(p);
  program.set_params(light);
  set_lights(program, view_lights);
  glProgramUniform1f(program.id(), program.uniform("near_plane"), g.near);
  glProgramUniform1f(program.id(), program.uniform("far_plane"), g.far);
  const Texture& normals = p.normals == EdgeNormals::Face ? g.face_normal : g.normal;
  float background = background_darkness(p);  // unlit: a background normal gets no light
  if (out.block_marks) {
    float mark = background > 0.0f ? 1.0f : 0.0f;  // the blocks outside `covered`
    glClearTexImage(out.block_marks->id(), 0, GL_RED, GL_FLOAT, &mark);
    glBindImageTexture(0, out.block_marks->id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_R32F);
  }
  glm::vec4 outside(background);
  if (out.darkness)
    pass_.draw_inside(program, {&normals, &g.normal}, {&out.lit, out.darkness}, covered, {outside, outside});
  else
    pass_.draw_inside(program, {&normals, &g.normal}, {&out.lit}, covered, {outside});
}

}  // namespace plumbago::gpu
