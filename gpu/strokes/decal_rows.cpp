// Decals and hatches as window paths on the GPU: see gpu/strokes/decal_rows.hpp.
#include "gpu/strokes/decal_rows.hpp"

#include <algorithm>
#include <cstring>
#include <string>
#include <utility>

#include "common/strokes/decal.hpp"
#include "common/util/memory_budget.hpp"

namespace plumbago::gpu {

namespace {

// shaders/strokes/decal_rows.comp's Record, Stroke, DecalPoint, Objects and Object (std430).
struct RecordRow {
  glm::dvec4 local;  // w: its pressure
  glm::uvec4 at;     // its object, its face
  uint32_t pad[4];
};
struct StrokeRow {
  uint32_t first_record, count, first_point, style, object, flags, pad[2];
  double alpha, width;
};
struct ScratchPoint {
  glm::dvec4 world;
  glm::dvec2 window;
  double depth, pressure;
  uint32_t object, key, pad[2];
  double pad2[2];
};
struct FrameRow {
  glm::dmat4 clip, view;  // world to clip, to view
};
struct ObjectRow {
  glm::dmat4 model;
  uint32_t first_key, pad[7];
};
static_assert(sizeof(RecordRow) == 64 && sizeof(StrokeRow) == 48 && sizeof(ScratchPoint) == 96 &&
              sizeof(FrameRow) == 256 && sizeof(ObjectRow) == 160);

// The points of `decal` in object space (common/strokes/decal.hpp decal_point_local).
void add_records(const Scene& scene, const ProjectedDecal& decal, std::vector<RecordRow>& out) {
  for (const DecalPoint& p : decal.points) {
    const glm::dvec3 local = p.object == kMissed ? glm::dvec3(0.0) : decal_point_local(scene, p);
    out.push_back({glm::dvec4(local, p.pressure), glm::uvec4(p.object, p.face, 0u, 0u), {}});
  }
}

// `rows` in a buffer, of one row at least.
template <class Row>
Buffer rows_buffer(std::vector<Row> rows) {
  rows.resize(std::max<size_t>(rows.size(), 1));
  return make_buffer(rows.data(), rows.size() * sizeof(Row));
}

}  // namespace

DecalRows::DecalRows(const Scene& scene, const DecalSurface& decals)
    : points_step_(Program::compute("strokes/decal_rows.comp", "#define STEP_POINTS\n")),
      rows_("strokes/decal_rows.comp"),
      decals_(decals),
      first_key_(first_faces(scene)) {
  std::vector<RecordRow> records;
  for (const ProjectedDecal& d : decals) {
    first_record_.push_back(uint32_t(records.size()));
    add_records(scene, d, records);
  }
  check_memory_budget("the decal and hatch points of " + std::to_string(records.size()) + " on the GPU",
                      double(records.size()) * double(sizeof(RecordRow) + sizeof(ScratchPoint)));
  fixed_ = rows_buffer(std::move(records));
}

size_t DecalRows::points(const SurfaceStrokes& drawn) {
  size_t n = 0;
  for (const SurfaceStroke& s : drawn.drawn) n += s.decal->points.size();
  return n;
}

void DecalRows::place_points(const Scene& scene, const SurfaceStrokes& drawn, const RowFrame& frame) {
  std::vector<StrokeRow> strokes;
  std::vector<RecordRow> moving;  // this frame's copies' points
  uint32_t next = 0;
  for (const SurfaceStroke& s : drawn.drawn) {
    const bool copy = s.decal != &decals_.at(s.index);
    const uint32_t first = copy ? uint32_t(moving.size()) : first_record_[s.index],
                   n = uint32_t(s.decal->points.size());
    if (copy) add_records(scene, *s.decal, moving);
    const uint32_t flags = (copy ? 1u : 0u) | (s.decal->hatch.group >= 0 ? 2u : 0u);
    strokes.push_back({first, n, next, 3 + s.index, s.object, flags, {}, s.weight.alpha, s.weight.width});
    next += n;
  }
  strokes_ = strokes.size();
  strokes_buffer_ = rows_buffer(std::move(strokes));
  const Buffer moving_buffer = rows_buffer(std::move(moving));
  const WindowProjection project(scene.camera, frame.width, frame.height);
  std::vector<ObjectRow> objects(scene.objects.size());
  for (uint32_t o = 0; o < scene.objects.size(); ++o)
    objects[o] = {glm::dmat4(scene.objects[o].transform), first_key_[o], {}};
  // Objects: the frame's view, then the objects (not double uniforms: OSMesa has no such entries).
  std::vector<unsigned char> object_bytes(sizeof(FrameRow) + scene.objects.size() * sizeof(ObjectRow));
  const FrameRow view_row{project.clip, project.view};
  std::memcpy(object_bytes.data(), &view_row, sizeof view_row);
  std::memcpy(object_bytes.data() + sizeof view_row, objects.data(), scene.objects.size() * sizeof(ObjectRow));
  const Buffer object_rows = make_buffer(object_bytes.data(), object_bytes.size());
  scratch_.reserve(std::max<uint32_t>(next, 1) * sizeof(ScratchPoint));
  const GLuint p = points_step_.id();
  glProgramUniform1f(p, points_step_.uniform("width"), float(frame.width));
  glProgramUniform1f(p, points_step_.uniform("height"), float(frame.height));
  glProgramUniform1ui(p, points_step_.uniform("source_count"), GLuint(strokes_));
  const std::pair<GLuint, const Buffer*> bound[] = {
      {1, &strokes_buffer_}, {2, &scratch_.buffer}, {5, &fixed_}, {6, &moving_buffer}, {7, &object_rows}};
  for (auto [b, buffer] : bound) glBindBufferBase(GL_SHADER_STORAGE_BUFFER, b, buffer->id());
  over_rows(points_step_, strokes_);
}

void DecalRows::operator()(const Scene& scene, const SurfaceStrokes& drawn, const RowFrame& frame, uint32_t first_point,
                           const Buffer& counts, const UploadedPaths& table) {
  if (drawn.drawn.empty()) return;  // the counts stay 0
  place_points(scene, drawn, frame);
  rows_(frame, strokes_, first_point, counts, table, {&strokes_buffer_, &scratch_.buffer});
}

}  // namespace plumbago::gpu
