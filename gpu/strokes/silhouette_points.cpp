// Silhouette path points on the GPU: see gpu/strokes/silhouette_points.hpp.
#include "gpu/strokes/silhouette_points.hpp"

#include "common/util/memory_budget.hpp"
#include "gpu/core/stage.hpp"

namespace plumbago::gpu {

namespace {

// shaders/strokes/silhouette_points.comp's Object (std430).
struct ObjectRow {
  glm::dmat4 model;
  glm::dvec4 eye;
  uint32_t first_record, first_vertex, pad[6];
};
static_assert(sizeof(ObjectRow) == 192);

Program step(const char* name) {
  return Program::compute("strokes/silhouette_points.comp", table_prelude() + "#define " + name + "\n");
}

}  // namespace

SilhouettePoints::SilhouettePoints(const Scene& scene, const LineMeshes& meshes, const StrokeMeshes& shared)
    : args_(step("STEP_ARGS")), points_(step("STEP_POINTS")), meshes_(shared) {
  const std::vector<uint32_t> first = first_faces(scene);
  const size_t records = first.back();
  check_memory_budget(
      "the silhouette points of " + std::to_string(records) + " faces on the GPU",
      double(records) * double(9 * sizeof(double) + 2 * (sizeof(SilhouettePoint) + sizeof(glm::dvec4))));
  std::vector<double> normals(std::max<size_t>(9 * records, 1), 0.0);
  for (uint32_t o = 0; o < scene.objects.size(); ++o) {
    const FeatureLineMesh* lines = line_mesh(meshes, o);
    if (!lines) continue;
    for (uint32_t f = 0; f < scene.objects[o].mesh->triangles.size(); ++f)
      for (int k = 0; k < 3; ++k)
        for (int c = 0; c < 3; ++c)
          normals[9 * (first[o] + f) + 3 * size_t(k) + size_t(c)] = lines->corner_normals()[3 * f + k][c];
  }
  normals_ = make_buffer(normals.data(), normals.size() * sizeof(double));
  args_buffer_ = make_buffer(nullptr, sizeof(glm::uvec4));
  rows_ = make_buffer(nullptr, silhouette_point_rows(records) * sizeof(SilhouettePoint));
  worlds_ = make_buffer(nullptr, silhouette_point_rows(records) * sizeof(glm::dvec4));
}

void SilhouettePoints::place(const Scene& scene, const LineMeshes& meshes, const Texture& paths,
                             const Texture& crossings, bool normalized) {
  const std::vector<uint32_t> first = first_faces(scene);
  std::vector<ObjectRow> objects;
  for (uint32_t o = 0; o < scene.objects.size(); ++o) {
    if (!line_mesh(meshes, o)) continue;
    glm::dmat4 model(scene.objects[o].transform);
    objects.push_back({model,
                       glm::dvec4(eye_in_object_space(model, glm::dvec3(scene.camera.eye)), 1.0),
                       first[o],
                       meshes_.first_vertex[o],
                       {}});
  }
  const WindowProjection project(scene.camera, scene.width, scene.height);
  const glm::dmat4 frame[2] = {project.clip, project.view};
  Buffer object_rows = make_buffer(objects.data(), objects.size() * sizeof(ObjectRow));
  Buffer frame_rows = make_buffer(frame, sizeof frame);
  for (const Program* p : {&args_, &points_}) bind_textures(*p, {{"paths", &paths}, {"crossings", &crossings}});
  glProgramUniform1i(points_.id(), points_.uniform("normalized"), normalized);
  glProgramUniform1ui(points_.id(), points_.uniform("object_count"), GLuint(objects.size()));
  glProgramUniform1f(points_.id(), points_.uniform("width"), float(scene.width));
  glProgramUniform1f(points_.id(), points_.uniform("height"), float(scene.height));
  const Buffer* bound[] = {&args_buffer_, &object_rows, &meshes_.positions, &meshes_.faces,
                           &normals_,     &rows_,       &frame_rows,        &worlds_};
  for (GLuint b = 0; b < 8; ++b) glBindBufferBase(GL_SHADER_STORAGE_BUFFER, b, bound[b]->id());
  glUseProgram(args_.id());
  glDispatchCompute(1, 1, 1);
  glMemoryBarrier(GL_COMMAND_BARRIER_BIT | GL_SHADER_STORAGE_BARRIER_BIT);
  glUseProgram(points_.id());
  glBindBuffer(GL_DISPATCH_INDIRECT_BUFFER, args_buffer_.id());
  glDispatchComputeIndirect(0);
  glBindBuffer(GL_DISPATCH_INDIRECT_BUFFER, 0);
  glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT | GL_SHADER_STORAGE_BARRIER_BIT);
}

std::vector<ChainPath> SilhouettePoints::read(const Scene& scene, const LineMeshes& meshes,
                                              const Texture& paths) const {
  // The counts, the paths' rows, then their points.
  const std::vector<float> counts = read_table(paths, 4, 1);
  const auto path_count = size_t(counts[0]), point_count = size_t(counts[1]);
  std::vector<SilhouettePoint> rows(point_count);
  read_buffer(rows_, rows.data(), rows.size() * sizeof(SilhouettePoint));
  return chain_paths(scene, meshes, read_table(paths, 4, path_count + 1), rows);
}

}  // namespace plumbago::gpu
