// What a scene's buffers would take, checked against the memory budget before any is
// made (common/util/memory_budget.hpp).
#include <algorithm>
#include <cstdio>
#include <set>
#include <stdexcept>
#include <vector>

#include "common/core/stage.hpp"
#include "common/pencil/paper.hpp"
#include "common/pencil/pencil_textures.hpp"
#include "common/scene/scene.hpp"
#include "common/sketchy/sketchy.hpp"
#include "common/util/memory_budget.hpp"
#include "common/util/noise.hpp"

namespace plumbago {

double frame_bytes_per_pixel() {
  double bytes = 0;
  for (const StageDesc& s : stage_table())
    if (s.kind == StageKind::Frame)
      for (const Output& o : s.outputs) bytes += 4.0 * o.channels;
  return bytes;
}

namespace {

struct Part {
  std::string what;
  double bytes;
};

// The GPU projects a stroke file's decals through a G-buffer rendered at the file's
// resolution (gpu/strokes/decal.cpp): its targets (96 bytes a pixel), depth buffer (4) and
// the ids read back (8), one file at a time; the ids of every file are kept (8 each).
constexpr double kTextureCopies = 2;
constexpr double kProjectionBytesPerPixel = 108, kKeptIdsBytesPerPixel = 8;

std::string square(int size) { return std::to_string(size) + "x" + std::to_string(size); }

// Whether a backend projects the file's strokes onto the surface: decals and hatching.
bool projected(const StrokeFile& file) {
  return std::any_of(file.strokes.begin(), file.strokes.end(), [](const DrawnStroke& s) {
    return s.role == StrokeRole::Decal || s.role == StrokeRole::Hatching;
  });
}

const StrokeFile* largest_stroke_file(const Scene& scene) {
  const StrokeFile* largest = nullptr;
  for (const StrokeFile& f : scene.stroke_files)
    if (projected(f) && (!largest || double(f.width) * f.height > double(largest->width) * largest->height))
      largest = &f;
  return largest;
}

// The scene's large allocations: its meshes, the frame's buffers, the textures its
// parameters size (every float texel 4 bytes, kept by the program and copied to the GPU:
// kTextureCopies).
std::vector<Part> scene_parts(const Scene& scene) {
  const auto pencil = scene.params.get<PencilTexturesParams>();
  const auto paper = scene.params.get<PaperParams>();
  const auto noise = scene.params.get<NoiseTextureParams>();
  const auto sketchy = scene.params.get<SketchyParams>();
  std::vector<Part> parts = {
      {"the frame's buffers (" + std::to_string(scene.width) + "x" + std::to_string(scene.height) + " pixels, " +
           std::to_string(int(frame_bytes_per_pixel())) + " bytes each)",
       double(scene.width) * scene.height * frame_bytes_per_pixel()},
      {"the pencil stack (pencil_textures.layers " + std::to_string(pencil.layers) + " of pencil_textures.size " +
           square(pencil.size) + ")",
       kTextureCopies * 4.0 * pencil.layers * pencil.size * pencil.size},
      {"the paper (paper.size " + square(paper.size) + ", height and normal)",
       kTextureCopies * 16.0 * paper.size * paper.size},
      {"the noise texture (noise.size " + square(noise.size) + ")", kTextureCopies * 4.0 * noise.size * noise.size},
      {"the 3D noise (sketchy.noise3d_size " + std::to_string(sketchy.noise3d_size) + "^3)",
       kTextureCopies * 4.0 * sketchy.noise3d_size * sketchy.noise3d_size * sketchy.noise3d_size}};
  std::set<const Mesh*> meshes;  // a file named twice is loaded once
  double mesh_total = 0;
  for (const SceneObject& o : scene.objects)
    if (meshes.insert(o.mesh.get()).second)
      mesh_total += mesh_bytes(double(o.mesh->positions.size()), double(o.mesh->triangles.size()));
  parts.push_back({"the meshes", mesh_total});
  if (const StrokeFile* largest = largest_stroke_file(scene)) {
    double kept = 0;
    for (const StrokeFile& f : scene.stroke_files)
      if (projected(f)) kept += kKeptIdsBytesPerPixel * f.width * f.height;
    parts.push_back({"the GPU's projection of stroke file " + largest->source + " (" + std::to_string(largest->width) +
                         "x" + std::to_string(largest->height) + " pixels)",
                     kProjectionBytesPerPixel * largest->width * largest->height + kept});
  }
  return parts;
}

std::string gb(double bytes) {
  char text[32];
  std::snprintf(text, sizeof text, "%.2f GB", bytes / 1e9);
  return text;
}

}  // namespace

void check_scene_memory(const Scene& scene) {
  std::vector<Part> parts = scene_parts(scene);
  double total = 0;
  for (const Part& p : parts) total += p.bytes;
  std::sort(parts.begin(), parts.end(), [](const Part& a, const Part& b) { return a.bytes > b.bytes; });
  if (std::string why = over_memory_budget(scene.source + ": the scene", total); !why.empty())
    throw std::length_error(why + ": mostly " + parts[0].what + ", " + gb(parts[0].bytes) + ", and " + parts[1].what +
                            ", " + gb(parts[1].bytes));
}

}  // namespace plumbago
