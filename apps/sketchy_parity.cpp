#include "apps/sketchy_parity.hpp"

#include <algorithm>

#include "common/preprocess.hpp"
#include "common/sketchy.hpp"
#include "gpu/context.hpp"
#include "gpu/sketchy_composite.hpp"
#include "gpu/sketchy_enlarged.hpp"
#include "gpu/sketchy_maps.hpp"
#include "reference/gbuffer.hpp"
#include "reference/sketchy_composite.hpp"
#include "reference/sketchy_enlarged.hpp"
#include "reference/sketchy_maps.hpp"

namespace plumbago {

namespace {

// Pixels covered in both images whose 3x3 neighborhood is covered in both: coverage
// itself is a raster-vs-ray question (the G-buffer's band), not the stage's.
Image covered_interior(const Image& a, const Image& b) {
  Image m(a.width, a.height, 1);
  for (int y = 0; y < a.height; ++y)
    for (int x = 0; x < a.width; ++x) {
      bool inside = true;
      for (int dy = -1; dy <= 1 && inside; ++dy)
        for (int dx = -1; dx <= 1 && inside; ++dx) {
          int nx = std::clamp(x + dx, 0, a.width - 1), ny = std::clamp(y + dy, 0, a.height - 1);
          inside = a.at(nx, ny, 3) > 0 && b.at(nx, ny, 3) > 0;
        }
      m.at(x, y) = inside ? 1.0f : 0.0f;
    }
  return m;
}

Image channel(const Image& img, int c) {
  Image out(img.width, img.height, 1);
  for (size_t i = 0; i < out.pixels(); ++i) out.data[i] = img.data[i * size_t(img.channels) + size_t(c)];
  return out;
}

}  // namespace

std::vector<StageParity> sketchy_enlarged_parity(const Scene& scene) {
  Scene enlarged = enlarged_scene(sketchy_objects(scene));
  if (enlarged.objects.empty()) return {};
  Image ref = reference::enlarged_noise_coordinates(enlarged, scene.width, scene.height);
  gpu::Texture out = gpu::make_texture(scene.width, scene.height, GL_RGBA32F);
  gpu::SketchyEnlargedPass(enlarged).render(scene.camera, out);
  Image ras = gpu::download_texture(out, 4);
  gpu::Context::get().check_errors("sketchy_enlarged parity");
  Image mask = covered_interior(ref, ras);
  return {compared("sketchy_enlarged.noise_coordinates", ref, ras, parity_tolerance::kBary, &mask,
                   "raster vs ray on the enlarged objects; pixels covered with their 3x3 neighborhood in both; "
                   "tolerance of the barycentrics (the coordinates are below 1)")};
}

std::vector<StageParity> sketchy_maps_parity(const Scene& scene) {
  Scene sketchy = sketchy_objects(scene);
  if (sketchy.objects.empty()) return {};
  GBuffer g = reference::trace_gbuffer(sketchy, scene.width, scene.height);
  auto p = scene.params.get<EdgeDetectParams>();
  reference::SketchyMaps ref = reference::sketchy_maps(g, object_colors(sketchy), p);
  gpu::GBufferTargets inputs = gpu::upload_gbuffer(g);
  gpu::Texture edge = gpu::make_texture(scene.width, scene.height, GL_RG32F);
  gpu::Texture shade = gpu::make_texture(scene.width, scene.height, GL_RGBA8);
  gpu::SketchyMapsPass(object_colors(sketchy)).run(inputs, p, edge, shade, filter_rect(sketchy, 1));
  Image gpu_edge = gpu::download_texture(edge, 2), gpu_shade = gpu::download_texture(shade, 4);
  gpu::Context::get().check_errors("sketchy_maps parity");
  return {compared("sketchy_maps.edge_darkness", channel(ref.edge, 0), channel(gpu_edge, 0), parity_tolerance::kFloat,
                   nullptr, "both fed the reference sketchy G-buffer; float target"),
          compared("sketchy_maps.edge_depth", channel(ref.edge, 1), channel(gpu_edge, 1), parity_tolerance::kFloat,
                   nullptr, "linear depth, the same texels picked; float target"),
          compared("sketchy_maps.shade", ref.shade, gpu_shade, parity_tolerance::kByte, nullptr,
                   "object colors and coverage; 8-bit target")};
}

std::vector<StageParity> sketchy_composite_parity(const Scene& scene) {
  Scene sketchy = sketchy_objects(scene);
  if (sketchy.objects.empty()) return {};
  auto sp = scene.params.get<SketchyParams>();
  GBuffer g = reference::trace_gbuffer(sketchy, scene.width, scene.height);
  reference::SketchyMaps maps = reference::sketchy_maps(g, object_colors(sketchy), scene.params.get<EdgeDetectParams>());
  SketchyNoise noise = make_sketchy_noise(scene.params, scene.seed);
  Image coords = sp.style == SketchyStyle::Object
                     ? reference::enlarged_noise_coordinates(enlarged_scene(sketchy), scene.width, scene.height)
                     : Image(scene.width, scene.height, 4);
  reference::SketchyFrame ref = reference::sketchy_composite({maps, g, noise, coords}, sp, Image(), Image());

  gpu::Texture edge = gpu::upload_texture(maps.edge, GL_RG32F), shade = gpu::upload_texture(maps.shade, GL_RGBA8);
  gpu::set_sampling(edge, GL_LINEAR, GL_CLAMP_TO_EDGE, GL_CLAMP_TO_EDGE);
  gpu::GBufferTargets inputs = gpu::upload_gbuffer(g);
  gpu::SketchyNoiseTextures textures = gpu::upload_sketchy_noise(noise);
  gpu::Texture coord_texture = gpu::upload_texture(coords, GL_RGBA32F);
  gpu::Texture color = gpu::make_texture(scene.width, scene.height, GL_RGBA8);
  gpu::Texture depth = gpu::make_texture(scene.width, scene.height, GL_R32F);
  gpu::SketchyCompositePass().run({edge, shade, inputs, textures, coord_texture}, sp, color, nullptr, depth,
                                  composite_rect(sketchy, scene.width, scene.height));
  Image gpu_color = gpu::download_texture(color, 3), gpu_depth = gpu::download_texture(depth, 1);
  gpu::Context::get().check_errors("sketchy_composite parity");
  const char* note = "both fed the reference maps, sketchy G-buffer, noise and noise coordinates; over white paper";
  return {compared("sketchy_composite.color", ref.color, gpu_color, parity_tolerance::kByte, nullptr, note),
          compared("sketchy_composite.depth", ref.depth, gpu_depth, parity_tolerance::kFloat, nullptr, note)};
}

}  // namespace plumbago
