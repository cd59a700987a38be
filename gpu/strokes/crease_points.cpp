// Crease and border points on the GPU (Kalnins et al. 2002, §4.5), the twin of
// reference/strokes/crease_points.cpp: one invocation per path point
// (shaders/strokes/crease_points.comp), from the meshes, the points and the faces around
// their segments, uploaded once. Nothing is read back.
#include "common/strokes/crease_points.hpp"

#include <glm/gtc/type_ptr.hpp>

#include "common/strokes/strokes.hpp"
#include "gpu/core/stage.hpp"
#include "gpu/scene/mesh_buffers.hpp"

namespace plumbago::gpu {

namespace {

// The records of one stroke object: [first, first + count) of the table.
struct ObjectRecords {
  MeshBuffers mesh;
  uint32_t first, count;
};

class CreasePointsPass : public GpuPass {
 public:
  explicit CreasePointsPass(GpuFrame& f)
      : program_(Program::compute("strokes/crease_points.comp", table_prelude())), first_key_(first_faces(f.scene)) {
    std::vector<CreaseRecord> records = crease_records(f.scene, f.get(kLineMeshes));
    std::vector<glm::uvec4> packed;
    std::vector<uint32_t> around;
    for (const CreaseRecord& r : records) {
      if (objects_.empty() || objects_.back().mesh.object != r.object)
        objects_.push_back({upload_mesh(f.scene, r.object), uint32_t(packed.size()), 0});
      ++objects_.back().count;
      packed.emplace_back(r.vertex, uint32_t(around.size()), uint32_t(r.faces.size()), 0u);
      around.insert(around.end(), r.faces.begin(), r.faces.end());
    }
    records_ = packed.size();
    packed.emplace_back(0u), around.push_back(0);  // never an empty buffer
    packed_ = make_buffer(packed.data(), packed.size() * sizeof(glm::uvec4));
    around_ = make_buffer(around.data(), around.size() * sizeof(uint32_t));
  }

  void run(GpuFrame& f) override {
    const Texture &window = table_target(f, records_, kCreaseWindow), &faces = table_target(f, records_, kCreaseFaces);
    glUseProgram(program_.id());
    glProgramUniform2f(program_.id(), program_.uniform("window_size"), float(f.scene.width), float(f.scene.height));
    glBindImageTexture(0, window.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, window.internal_format);
    glBindImageTexture(1, faces.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, faces.internal_format);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 2, packed_.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 3, around_.id());
    for (const ObjectRecords& o : objects_) dispatch(f, o);
    glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_TEXTURE_UPDATE_BARRIER_BIT);
  }

 private:
  void dispatch(const GpuFrame& f, const ObjectRecords& o) {
    glm::dmat4 m(f.scene.objects[o.mesh.object].transform);
    glm::vec3 eye(eye_in_object_space(m, glm::dvec3(f.scene.camera.eye)));
    GLuint p = program_.id();
    object_uniforms(program_, f.scene, o.mesh.object);
    glProgramUniform3fv(p, program_.uniform("eye"), 1, glm::value_ptr(eye));
    glProgramUniform1f(p, program_.uniform("handedness"), glm::determinant(glm::dmat3(m)) < 0 ? -1.0f : 1.0f);
    glProgramUniform1ui(p, program_.uniform("first_key"), first_key_[o.mesh.object] + 1);
    glProgramUniform1ui(p, program_.uniform("first_record"), o.first);
    glProgramUniform1ui(p, program_.uniform("record_count"), o.count);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, o.mesh.positions.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, o.mesh.corners.id());
    dispatch_in_chunks(program_, o.count, "first_point");
  }

  Program program_;
  std::vector<uint32_t> first_key_;
  std::vector<ObjectRecords> objects_;
  size_t records_ = 0;
  Buffer packed_, around_;
};

}  // namespace

PLUMBAGO_GPU_PASS(crease_points, {{"crease_points"}, {}, make_pass<CreasePointsPass>, Probe::Compute});

}  // namespace plumbago::gpu
