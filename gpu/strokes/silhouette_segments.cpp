// Silhouette segments on the GPU (Kalnins et al. 2002, §4.5), the twin of
// reference/strokes/silhouette_segments.cpp: one invocation per face of each stroke object
// (shaders/strokes/silhouette_segments.comp), from its corners and slot orientations
// (gpu/strokes/stroke_meshes.hpp, shared with the silhouette points) and its crease-aware
// corner normals, uploaded once. Nothing is read back.
#include "common/strokes/silhouette_segments.hpp"

#include <glm/gtc/type_ptr.hpp>

#include "common/strokes/strokes.hpp"
#include "gpu/core/stage.hpp"
#include "gpu/scene/mesh_buffers.hpp"
#include "gpu/strokes/stroke_meshes.hpp"

namespace plumbago::gpu {

namespace {

// The crease-aware corner normals of every face record, 3 a record (0 for an object without
// strokes), in float.
Buffer corner_normals(const Scene& scene, const LineMeshes& meshes) {
  const std::vector<uint32_t> first = first_faces(scene);
  std::vector<glm::vec4> normals(std::max<size_t>(3 * size_t(first.back()), 1), glm::vec4(0.0f));
  for (uint32_t o = 0; o < scene.objects.size(); ++o)
    if (const FeatureLineMesh* lines = line_mesh(meshes, o))
      for (size_t c = 0; c < lines->corner_normals().size(); ++c)
        normals[3 * size_t(first[o]) + c] = glm::vec4(glm::vec3(lines->corner_normals()[c]), 0.0f);
  return make_buffer(normals.data(), normals.size() * sizeof(glm::vec4));
}

class SilhouetteSegmentsPass : public GpuPass {
 public:
  explicit SilhouetteSegmentsPass(GpuFrame& f)
      : program_(Program::compute("strokes/silhouette_segments.comp", table_prelude())),
        meshes_(f.scene, f.get(kLineMeshes)),
        normals_(corner_normals(f.scene, f.get(kLineMeshes))),
        first_record_(first_faces(f.scene)) {
    records_ = first_record_.back();
    for (uint32_t o = 0; o < f.scene.objects.size(); ++o)
      if (line_mesh(f.get(kLineMeshes), o)) objects_.push_back(o);
    f.put(kStrokeMeshes, meshes_);  // the silhouette points' too (gpu/strokes/id_image.cpp)
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
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, meshes_.positions.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, meshes_.faces.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 2, normals_.id());
    for (uint32_t o : objects_) dispatch(f, o);
    glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_TEXTURE_UPDATE_BARRIER_BIT);
  }

 private:
  void set_frame_uniforms(const GpuFrame& f) {
    GLuint p = program_.id();
    glProgramUniform1i(p, program_.uniform("normalized"), f.params<StrokesParams>().silhouette_normalized);
    glProgramUniform1f(p, program_.uniform("near"), f.scene.camera.near);
    glProgramUniform2f(p, program_.uniform("window_size"), float(f.scene.width), float(f.scene.height));
  }

  void dispatch(const GpuFrame& f, uint32_t object) {
    glm::vec3 eye(eye_in_object_space(glm::dmat4(f.scene.objects[object].transform), glm::dvec3(f.scene.camera.eye)));
    GLuint p = program_.id();
    const auto faces = uint32_t(f.scene.objects[object].mesh->triangles.size());
    object_uniforms(program_, f.scene, object);
    glProgramUniform3fv(p, program_.uniform("eye"), 1, glm::value_ptr(eye));
    glProgramUniform1ui(p, program_.uniform("face_count"), faces);
    glProgramUniform1ui(p, program_.uniform("first_record"), first_record_[object]);
    glProgramUniform1ui(p, program_.uniform("first_vertex"), meshes_.first_vertex[object]);
    dispatch_in_chunks(program_, faces, "first_face");
  }

  Program program_;
  StrokeMeshes meshes_;
  Buffer normals_;
  std::vector<uint32_t> first_record_;  // first_faces
  bool cleared_ = false;
  uint32_t records_ = 0;
  std::vector<uint32_t> objects_;  // the stroke objects
};

}  // namespace

PLUMBAGO_GPU_PASS(silhouette_segments,
                  {{"silhouette_segments"}, {}, make_pass<SilhouetteSegmentsPass>, Probe::Compute});

}  // namespace plumbago::gpu
