// Silhouette segments on the GPU (Kalnins et al. 2002, §4.5), the twin of
// reference/strokes/silhouette_segments.cpp: one invocation per face of each stroke object
// (shaders/strokes/silhouette_segments.comp), from its corners, crease-aware corner normals
// and slot orientations, uploaded once. Nothing is read back.
#include "common/strokes/silhouette_segments.hpp"

#include <glm/gtc/type_ptr.hpp>

#include "common/strokes/strokes.hpp"
#include "gpu/core/stage.hpp"
#include "gpu/scene/mesh_buffers.hpp"

namespace plumbago::gpu {

namespace {

// A stroke object's mesh with its slot orientations and crease-aware corner normals.
struct ObjectBuffers {
  MeshBuffers mesh;
  uint32_t first_record;
  Buffer normals;
};

ObjectBuffers upload(const Scene& scene, const FeatureLineMesh& lines, uint32_t object, uint32_t first_record) {
  std::vector<glm::vec4> normals;
  for (glm::dvec3 n : lines.corner_normals()) normals.emplace_back(glm::vec3(n), 0.0f);
  if (normals.empty()) normals.emplace_back(0.0f);
  return {upload_mesh(scene, object, [&](uint32_t f) { return lines.reversed_slots(f); }), first_record,
          make_buffer(normals.data(), normals.size() * sizeof(glm::vec4))};
}

class SilhouetteSegmentsPass : public GpuPass {
 public:
  explicit SilhouetteSegmentsPass(GpuFrame& f)
      : program_(Program::compute("strokes/silhouette_segments.comp", table_prelude())) {
    std::vector<uint32_t> first = first_faces(f.scene);
    records_ = first.back();
    for (uint32_t o = 0; o < f.scene.objects.size(); ++o)
      if (const FeatureLineMesh* lines = line_mesh(f.get(kLineMeshes), o))
        objects_.push_back(upload(f.scene, *lines, o, first[o]));
  }

  // Every face record of a stroke object is written each frame (0 where no segment); the
  // others' stay 0 from the one clear when the tables are made.
  void run(GpuFrame& f) override {
    const Texture* tables[] = {&table_target(f, records_, kSegmentEnds), &table_target(f, records_, kSegmentFacing),
                               &table_target(f, records_, kSegmentSlots)};
    const float zero[4] = {0, 0, 0, 0};
    glUseProgram(program_.id());
    for (GLuint unit = 0; unit < 3; ++unit) {
      if (!cleared_) glClearTexImage(tables[unit]->id(), 0, GL_RGBA, GL_FLOAT, zero);
      glBindImageTexture(unit, tables[unit]->id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, tables[unit]->internal_format);
    }
    cleared_ = true;
    set_frame_uniforms(f);
    for (const ObjectBuffers& o : objects_) dispatch(f, o);
    glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_TEXTURE_UPDATE_BARRIER_BIT);
  }

 private:
  void set_frame_uniforms(const GpuFrame& f) {
    GLuint p = program_.id();
    glProgramUniform1i(p, program_.uniform("normalized"), f.params<StrokesParams>().silhouette_normalized);
    glProgramUniform1f(p, program_.uniform("near"), f.scene.camera.near);
    glProgramUniform2f(p, program_.uniform("window_size"), float(f.scene.width), float(f.scene.height));
  }

  void dispatch(const GpuFrame& f, const ObjectBuffers& o) {
    const uint32_t object = o.mesh.object;
    glm::vec3 eye(eye_in_object_space(glm::dmat4(f.scene.objects[object].transform), glm::dvec3(f.scene.camera.eye)));
    GLuint p = program_.id();
    object_uniforms(program_, f.scene, object);
    glProgramUniform3fv(p, program_.uniform("eye"), 1, glm::value_ptr(eye));
    glProgramUniform1ui(p, program_.uniform("face_count"), o.mesh.faces);
    glProgramUniform1ui(p, program_.uniform("first_record"), o.first_record);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, o.mesh.positions.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, o.mesh.corners.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 2, o.normals.id());
    dispatch_in_chunks(program_, o.mesh.faces, "first_face");
  }

  Program program_;
  bool cleared_ = false;
  uint32_t records_ = 0;
  std::vector<ObjectBuffers> objects_;
};

}  // namespace

PLUMBAGO_GPU_PASS(silhouette_segments,
                  {{"silhouette_segments"}, {}, make_pass<SilhouetteSegmentsPass>, Probe::Compute});

}  // namespace plumbago::gpu
