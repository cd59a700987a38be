// A scene object's mesh kept in GPU memory for the passes that pull its vertices (the ID
// image's faces, the silhouette segments): object-space positions and, per face, its
// corners' vertices. Uploaded once; each frame sets only the object's matrices
// (object_uniforms).
#pragma once

#include <cstdint>
#include <functional>

#include "common/scene/scene.hpp"
#include "gpu/gl/program.hpp"

namespace plumbago::gpu {

struct MeshBuffers {
  uint32_t object = 0, faces = 0;
  Buffer positions;  // vec4 (x, 1) per vertex, std430
  Buffer corners;    // uvec4 per face: its three vertices, then `face_word` of it (0 without)
};

MeshBuffers upload_mesh(const Scene& scene, uint32_t object,
                        const std::function<uint32_t(uint32_t face)>& face_word = {});

// Sets the uniforms `clip` (object to clip space) and `depth_row` (object point (x, 1) to
// linear view depth d = -z_view) of `program` for scene object `object` this frame.
void object_uniforms(const Program& program, const Scene& scene, uint32_t object);

}  // namespace plumbago::gpu
