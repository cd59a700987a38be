// A scene object's mesh in GPU memory: see gpu/scene/mesh_buffers.hpp.
#include "gpu/scene/mesh_buffers.hpp"

#include <glm/gtc/type_ptr.hpp>

#include "common/strokes/strokes.hpp"

namespace plumbago::gpu {

MeshBuffers upload_mesh(const Scene& scene, uint32_t object, const std::function<uint32_t(uint32_t)>& face_word) {
  const Mesh& mesh = *scene.objects[object].mesh;
  std::vector<glm::vec4> positions;
  std::vector<glm::uvec4> corners;
  for (glm::vec3 p : mesh.positions) positions.emplace_back(p, 1.0f);
  for (uint32_t f = 0; f < mesh.triangles.size(); ++f) {
    const auto& t = mesh.triangles[f];
    corners.emplace_back(t[0], t[1], t[2], face_word ? face_word(f) : 0u);
  }
  if (positions.empty()) positions.emplace_back(0.0f);  // never an empty buffer
  if (corners.empty()) corners.emplace_back(0u);
  return {object, uint32_t(mesh.triangles.size()), make_buffer(positions.data(), positions.size() * sizeof(glm::vec4)),
          make_buffer(corners.data(), corners.size() * sizeof(glm::uvec4))};
}

void object_uniforms(const Program& program, const Scene& scene, uint32_t object) {
  WindowProjection camera(scene.camera, scene.width, scene.height);
  glm::dmat4 m(scene.objects[object].transform), view = camera.view * m;
  glm::mat4 clip(camera.clip * m);
  glm::vec4 depth(-glm::dvec4(view[0][2], view[1][2], view[2][2], view[3][2]));
  glProgramUniformMatrix4fv(program.id(), program.uniform("clip"), 1, GL_FALSE, glm::value_ptr(clip));
  glProgramUniform4fv(program.id(), program.uniform("depth_row"), 1, glm::value_ptr(depth));
}

}  // namespace plumbago::gpu
