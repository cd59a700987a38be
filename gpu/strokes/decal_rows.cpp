// Decals and hatches as window paths on the GPU: see gpu/strokes/decal_rows.hpp.
#include "gpu/strokes/decal_rows.hpp"

#include <algorithm>
#include <cstring>
#include <map>
#include <string>
#include <utility>

#include "common/strokes/decal.hpp"
#include "common/strokes/uv_chart.hpp"
#include "common/util/memory_budget.hpp"

namespace plumbago::gpu {

namespace {

// shaders/strokes/decal_rows.comp's Record, Stroke, DecalPoint, Objects and Object (std430).
struct RecordRow {
  glm::dvec4 local;  // w: its pressure
  glm::uvec4 at;     // its object, its face
  glm::dvec2 uv;     // a mobile hatch's point on its group's object: its (u, v)
};
struct StrokeRow {
  uint32_t first_record, count, first_point, style, object, flags, chart, pad;
  double alpha, width, copy_u, copy_scale, c_u;
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
// shaders/strokes/uv_chart.glsl's Chart and ChartFace (std430).
struct ChartRow {
  glm::dvec2 lo, hi;
  uint32_t cells, periodic, object, first_face, first_start, pad[3];
};
struct ChartFaceRow {
  glm::vec2 uv[3];
  float pad[2];
  glm::vec4 position[3];
};
static_assert(sizeof(RecordRow) == 64 && sizeof(StrokeRow) == 72 && sizeof(ScratchPoint) == 96 &&
              sizeof(FrameRow) == 256 && sizeof(ObjectRow) == 160 && sizeof(ChartRow) == 64 &&
              sizeof(ChartFaceRow) == 80);

// The points of `decal` in object space (common/strokes/decal.hpp decal_point_local); those of
// a mobile hatch on its group's object, with their (u, v) in the group's chart.
void add_records(const Scene& scene, const ProjectedDecal& decal, const MobileHatching::Travel& travel,
                 std::vector<RecordRow>& out) {
  for (const DecalPoint& p : decal.points) {
    const glm::dvec3 local = p.object == kMissed ? glm::dvec3(0.0) : decal_point_local(scene, p);
    const bool charted = travel.chart && p.object == travel.object;
    out.push_back({glm::dvec4(local, p.pressure), glm::uvec4(p.object, p.face, 0u, 0u),
                   charted ? travel.chart->uv(p.face, p.bary) : glm::dvec2(0.0)});
  }
}

// `chart` as shaders/strokes/uv_chart.glsl reads it, its rows appended to `faces` and `buckets`.
ChartRow add_chart(const UvChart& chart, uint32_t object, std::vector<ChartFaceRow>& faces,
                   std::vector<uint32_t>& buckets) {
  const ChartRow row{chart.lo(),
                     chart.hi(),
                     uint32_t(chart.cells()),
                     chart.periodic() ? 1u : 0u,
                     object,
                     uint32_t(faces.size()),
                     uint32_t(buckets.size()),
                     {}};
  const Mesh& mesh = chart.mesh();
  for (size_t f = 0; f < mesh.triangles.size(); ++f) {
    ChartFaceRow face{};
    for (int k = 0; k < 3; ++k)
      face.uv[k] = chart.corner_uvs()[3 * f + size_t(k)],
      face.position[k] = glm::vec4(mesh.positions[mesh.triangles[f][k]], 1.0f);
    faces.push_back(face);
  }
  const uint32_t listed = row.first_start + uint32_t(chart.starts().size());
  for (uint32_t start : chart.starts()) buckets.push_back(listed + start);
  buckets.insert(buckets.end(), chart.faces().begin(), chart.faces().end());
  return row;
}

// `rows` in a buffer, of one row at least.
template <class Row>
Buffer rows_buffer(std::vector<Row> rows) {
  rows.resize(std::max<size_t>(rows.size(), 1));
  return make_buffer(rows.data(), rows.size() * sizeof(Row));
}

}  // namespace

DecalRows::DecalRows(const Scene& scene, const DecalSurface& decals, const MobileHatching& mobile)
    : points_step_(Program::compute("strokes/decal_rows.comp", "#define STEP_POINTS\n")),
      rows_("strokes/decal_rows.comp"),
      first_key_(first_faces(scene)) {
  std::vector<RecordRow> records;
  std::vector<ChartRow> charts;
  std::vector<ChartFaceRow> faces;
  std::vector<uint32_t> buckets;
  std::map<const UvChart*, uint32_t> uploaded;
  for (size_t d = 0; d < decals.size(); ++d) {
    const MobileHatching::Travel travel = mobile.travel(d);
    first_record_.push_back(uint32_t(records.size()));
    add_records(scene, decals[d], travel, records);
    // a chart goes up once, however many groups travel on it
    chart_.push_back(travel.chart ? uploaded.emplace(travel.chart, uint32_t(charts.size())).first->second : 0u);
    if (travel.chart && chart_.back() == charts.size())
      charts.push_back(add_chart(*travel.chart, travel.object, faces, buckets));
  }
  check_memory_budget(
      "the decal and hatch points of " + std::to_string(records.size()) + " and their charts on the GPU",
      double(records.size()) * double(sizeof(RecordRow) + sizeof(ScratchPoint)) +
          double(faces.size()) * double(sizeof(ChartFaceRow)) + double(buckets.size()) * 4.0);
  fixed_ = rows_buffer(std::move(records));
  charts_ = rows_buffer(std::move(charts));
  chart_faces_ = rows_buffer(std::move(faces));
  buckets_ = rows_buffer(std::move(buckets));
}

size_t DecalRows::points(const SurfaceStrokes& drawn) {
  size_t n = 0;
  for (const SurfaceStroke& s : drawn.drawn) n += s.decal->points.size();
  return n;
}

void DecalRows::place_points(const Scene& scene, const SurfaceStrokes& drawn, const RowFrame& frame) {
  std::vector<StrokeRow> strokes;
  uint32_t next = 0;
  for (const SurfaceStroke& s : drawn.drawn) {
    const uint32_t n = uint32_t(s.decal->points.size());
    StrokeRow row{first_record_[s.index],
                  n,
                  next,
                  3 + s.index,
                  s.object,
                  s.decal->hatch.group >= 0 ? 2u : 0u,
                  chart_[s.index],
                  0,
                  s.weight.alpha,
                  s.weight.width,
                  0,
                  0,
                  0};
    if (s.copy >= 0) {  // moved on the GPU (uv_chart.glsl), from its group's placement
      const MobileHatching::Placement& at = drawn.placed.at(size_t(s.decal->hatch.group));
      row.flags |= 1u, row.copy_u = at.u.at(size_t(s.copy)), row.copy_scale = at.scale.at(size_t(s.copy));
      row.c_u = at.c.x;
    }
    strokes.push_back(row);
    next += n;
  }
  strokes_ = strokes.size();
  strokes_buffer_ = rows_buffer(std::move(strokes));
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
  const std::pair<GLuint, const Buffer*> bound[] = {{0, &charts_},    {1, &strokes_buffer_}, {2, &scratch_.buffer},
                                                    {3, &buckets_},   {5, &fixed_},          {6, &chart_faces_},
                                                    {7, &object_rows}};
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
