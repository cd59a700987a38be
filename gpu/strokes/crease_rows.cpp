// Crease and border paths as window paths on the GPU: see gpu/strokes/crease_rows.hpp.
#include "gpu/strokes/crease_rows.hpp"

#include <algorithm>
#include <string>

#include "common/strokes/crease_points.hpp"
#include "common/util/memory_budget.hpp"
#include "gpu/core/stage.hpp"

namespace plumbago::gpu {

namespace {

// shaders/strokes/crease_rows.comp's Object, CreasePoint and Frame (std430).
struct ObjectRow {
  glm::dmat4 model;
  uint32_t first_record, first_vertex, pad[6];
};
struct ScratchPoint {
  glm::dvec4 world;
  glm::dvec2 window;
  double depth, pad;
  glm::uvec2 faces, pad2;
  double pad3[2];
};
struct FrameRow {
  glm::dmat4 clip, view;  // world to clip, to view
  glm::dvec4 eye;         // world space
};
static_assert(sizeof(ObjectRow) == 160 && sizeof(ScratchPoint) == 96 && sizeof(FrameRow) == 288);

// Per crease and border path of `scene`'s stroke objects, in window_lines' order: its first
// record, its points, and flags (1 closed, 2 a border).
std::vector<glm::uvec4> path_defs(const Scene& scene, const LineMeshes& meshes) {
  std::vector<glm::uvec4> defs;
  uint32_t next = 0;
  auto add = [&](const FeaturePath& p, uint32_t border) {
    defs.emplace_back(next, uint32_t(p.points.size()), 0u, (p.closed ? 1u : 0u) | border);
    next += uint32_t(p.points.size());
  };
  for (uint32_t o = 0; o < scene.objects.size(); ++o) {
    const FeatureLineMesh* lines = line_mesh(meshes, o);
    if (!lines) continue;
    for (const FeaturePath& p : lines->creases_and_borders().creases) add(p, 0u);
    for (const FeaturePath& p : lines->creases_and_borders().borders) add(p, 2u);
  }
  return defs;
}

}  // namespace

CreaseRows::CreaseRows(const Scene& scene, const LineMeshes& meshes, const StrokeMeshes& shared)
    : points_step_(Program::compute("strokes/crease_rows.comp", "#define STEP_POINTS\n")),
      rows_("strokes/crease_rows.comp"),
      meshes_(shared),
      first_face_(first_faces(scene)) {
  rows_.set("face_count", first_face_.back());
  std::vector<glm::uvec4> packed, defs = path_defs(scene, meshes);
  std::vector<uint32_t> around;
  for (const CreaseRecord& r : crease_records(scene, meshes)) {
    packed.emplace_back(r.vertex, uint32_t(around.size()), uint32_t(r.faces.size()), r.object);
    around.insert(around.end(), r.faces.begin(), r.faces.end());
  }
  records_ = packed.size(), paths_ = defs.size();
  check_memory_budget("the crease and border points of " + std::to_string(records_) + " on the GPU",
                      double(records_) * double(sizeof(glm::uvec4) + sizeof(ScratchPoint)));
  packed.emplace_back(0u), around.push_back(0), defs.emplace_back(0u);  // never an empty buffer
  records_buffer_ = make_buffer(packed.data(), packed.size() * sizeof(glm::uvec4));
  around_ = make_buffer(around.data(), around.size() * sizeof(uint32_t));
  defs_ = make_buffer(defs.data(), defs.size() * sizeof(glm::uvec4));
  scratch_ = make_buffer(nullptr, std::max<size_t>(records_, 1) * sizeof(ScratchPoint));
}

void CreaseRows::place_points(const Scene& scene, const RowFrame& frame) {
  std::vector<ObjectRow> objects(scene.objects.size());
  for (uint32_t o = 0; o < scene.objects.size(); ++o)
    objects[o] = {glm::dmat4(scene.objects[o].transform), first_face_[o], meshes_.first_vertex[o], {}};
  Buffer object_rows = make_buffer(objects.data(), objects.size() * sizeof(ObjectRow));
  const WindowProjection project(scene.camera, frame.width, frame.height);
  const FrameRow view_row{project.clip, project.view, glm::dvec4(glm::dvec3(scene.camera.eye), 1.0)};
  Buffer frame_row = make_buffer(&view_row, sizeof view_row);  // not double uniforms: OSMesa has no such entries
  const GLuint p = points_step_.id();
  glProgramUniform1f(p, points_step_.uniform("width"), float(frame.width));
  glProgramUniform1f(p, points_step_.uniform("height"), float(frame.height));
  glProgramUniform1ui(p, points_step_.uniform("record_count"), GLuint(records_));
  const Buffer* bound[] = {&records_buffer_, &around_,  &meshes_.positions, &meshes_.faces,
                           &object_rows,     &scratch_, &frame_row};
  for (GLuint b = 0; b < 7; ++b) glBindBufferBase(GL_SHADER_STORAGE_BUFFER, b, bound[b]->id());
  dispatch_in_chunks(points_step_, records_, "first");
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
}

void CreaseRows::operator()(const Scene& scene, const RowFrame& frame, uint32_t first_point, const Buffer& counts,
                            const UploadedPaths& table) {
  place_points(scene, frame);
  rows_(frame, paths_, first_point, counts, table, {&defs_, &scratch_});
}

}  // namespace plumbago::gpu
