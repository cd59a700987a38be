#include "apps/parity.hpp"
#include "apps/sketchy_parity.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <map>
#include <stdexcept>

#include "common/compose.hpp"
#include "common/edge_detect.hpp"
#include "common/gbuffer.hpp"
#include "common/lights.hpp"
#include "common/paper.hpp"
#include "common/preprocess.hpp"
#include "gpu/compose.hpp"
#include "gpu/multi_contour.hpp"
#include "gpu/pencil_interior.hpp"
#include "gpu/pipeline.hpp"
#include "gpu/context.hpp"
#include "gpu/edge_detect.hpp"
#include "gpu/gbuffer.hpp"
#include "reference/compose.hpp"
#include "reference/contour_light.hpp"
#include "reference/multi_contour.hpp"
#include "reference/pencil_interior.hpp"
#include "reference/pipeline.hpp"
#include "reference/edge_detect.hpp"
#include "reference/gbuffer.hpp"
#include "reference/interior_intensity.hpp"

namespace plumbago {

namespace {

// SPEC §5 tolerances.
constexpr double kDepthTolerance = 1e-4;   // normalized depth, raster vs ray
constexpr double kNormalTolerance = 1e-3;  // unit normals, raster vs ray
// A float stage that samples textures bilinearly: llvmpipe filters float textures with
// float weights (tests/sampler_test.cpp: 1.2e-6), but the texture coordinates themselves
// come out of slightly different float expressions; measured max 2e-5 on llvmpipe.
// Hardware with 8-bit filter weights would need about 1/256 (SPEC 5).
constexpr double kSampledTolerance = 1e-3;
// Corner angles of SPEC 2.7: both backends evaluate the same float formula on the same
// world-space floats (GPU in the vertex shader); measured on llvmpipe: see the test.
constexpr double kAngleTolerance = 1e-3;
// End to end: at most this share of pixels may differ by more than 2/255 (measured on
// the built-in scenes and the shared models: see tests/end_to_end_test.cpp).
constexpr double kEndToEndShare = 0.05;
constexpr float kDepthJump = 0.01f;        // relative linear-depth step that makes a discontinuity

bool across_discontinuity(const GBuffer& g, int x, int y, int nx, int ny) {
  if (g.ids.at(x, y, 0) != g.ids.at(nx, ny, 0)) return true;
  float d = g.depth.at(x, y), dn = g.depth.at(nx, ny);
  return std::abs(d - dn) > kDepthJump * std::min(d, dn);
}

bool near_discontinuity(const GBuffer& g, int x, int y) {
  for (int dy = -1; dy <= 1; ++dy)
    for (int dx = -1; dx <= 1; ++dx) {
      int nx = std::clamp(x + dx, 0, g.depth.width - 1), ny = std::clamp(y + dy, 0, g.depth.height - 1);
      if (across_discontinuity(g, x, y, nx, ny)) return true;
    }
  return false;
}

Image same_triangle(const GBuffer& a, const GBuffer& b, const Image& interior) {
  Image m = interior;
  for (int y = 0; y < m.height; ++y)
    for (int x = 0; x < m.width; ++x)
      if (a.ids.at(x, y, 1) != b.ids.at(x, y, 1)) m.at(x, y) = 0;
  return m;
}

double share(const Image& mask) {
  double n = 0;
  for (float v : mask.data) n += v > 0.5f;
  return n / double(mask.pixels());
}

std::vector<StageParity> gbuffer_parity(const Scene& scene, const GBuffer& ref) {
  gpu::GBufferTargets targets = gpu::make_gbuffer_targets(scene.width, scene.height, GBufferFormat::RGBA32F);
  gpu::GBufferPass(scene).render(scene, targets);
  GBuffer ras = gpu::download_gbuffer(targets);
  gpu::Context::get().check_errors("gbuffer parity");
  Image interior = interior_mask(ref, ras), triangle = same_triangle(ref, ras, interior);
  Image covered(ref.ids.width, ref.ids.height, 1);
  for (size_t i = 0; i < covered.pixels(); ++i) covered.data[i] = ref.ids.data[i * 2] || ras.ids.data[i * 2];
  char band[160];
  std::snprintf(band, sizeof band, "interior %.1f%% of the image; band excluded %.2f%% of the image",
                100 * share(interior), 100 * (share(covered) - share(interior)));
  return {
      compared("gbuffer.depth", normalized_depth(ref), normalized_depth(ras), kDepthTolerance, &interior, band),
      compared("gbuffer.normal", ref.normal, ras.normal, kNormalTolerance, &interior, band),
      compared("gbuffer.face_normal", ref.face_normal, ras.face_normal, kNormalTolerance, &triangle,
               "interior pixels that both backends give the same triangle"),
      compared("gbuffer.bary", ref.bary, ras.bary, parity_tolerance::kBary, &triangle,
               "interior pixels that both backends give the same triangle"),
      compared("gbuffer.gouraud", ref.gouraud, ras.gouraud, kNormalTolerance, &interior, band),
  };
}

StageParity edge_parity(const Scene& scene, const GBuffer& ref) {
  auto p = scene.params.get<EdgeDetectParams>();
  gpu::GBufferTargets inputs = gpu::upload_gbuffer(ref);
  gpu::Texture out = gpu::make_texture(scene.width, scene.height, GL_R32F);
  gpu::Texture lit = gpu::make_texture(scene.width, scene.height, GL_R32F);
  gpu::EdgeDetectPass().run(inputs, p, view_space_lights(scene), scene.params.get<ContourLightParams>(), {lit, &out},
                            filter_rect(scene, 1));
  Image gpu_out = gpu::download_texture(out, 1);
  gpu::Context::get().check_errors("edge_detect parity");
  return compared("edge_detect", reference::contour_darkness(ref, p), gpu_out, parity_tolerance::kFloat, nullptr,
                  "both fed the reference G-buffer; float target");
}

// The inputs of multiple contour drawing (SPEC 2.4) from the reference: its lit contours
// d', the offset grids, the contour texture; and the GPU's copy inputs made from them.
struct ContourStageInputs {
  ContourParams p;
  Preprocessed pre;
  Image lit;
  gpu::ContourInputs inputs;
  gpu::Texture lit_texture;
  PixelRect covered;

  ContourStageInputs(const Scene& scene, const GBuffer& ref)
      : p(scene.params.get<ContourParams>()),
        pre(preprocess(scene, {"distortion", "contour_texture"})),
        lit(reference::lit_contour_darkness(reference::contour_darkness(ref, scene.params.get<EdgeDetectParams>()), ref,
                                            view_space_lights(scene), scene.params.get<ContourLightParams>())),
        inputs(gpu::make_contour_inputs(p, pre.offset_grids, pre.contour_texture, pre.texture_shifts, scene.width,
                                        scene.height)),
        lit_texture(gpu::upload_texture(lit, GL_R32F)),
        covered(contour_rect(scene, pre.offset_grids)) {}

  Image reference_darkness() const {
    return reference::multi_contour_darkness(lit, pre.offset_grids, pre.contour_texture, pre.texture_shifts, p);
  }
};

// An interior (1 - Gouraud stands in for it) and the paper color, composed with contours.
struct ComposeStageInputs {
  Image interior, paper;
  gpu::Texture interior_texture, paper_texture;

  ComposeStageInputs(const Scene& scene, const GBuffer& ref)
      : interior(ref.gouraud), paper(make_paper(scene.params.get<PaperParams>(), scene.seed).color) {
    for (float& v : interior.data) v = 1.0f - v;
    interior_texture = gpu::upload_texture(interior, GL_R32F);
    paper_texture = gpu::upload_texture(paper, GL_RGBA32F);
  }
  gpu::ComposeInputs gpu_inputs() const { return {interior_texture, true, paper_texture, true}; }
};

// Multiple contour drawing as its own pass, and as a frame draws it: inside the
// composition pass (gpu/compose.hpp), whose second output is then D_c.
std::vector<StageParity> multi_contour_parity(const Scene& scene, const GBuffer& ref) {
  ContourStageInputs c(scene, ref);
  gpu::Texture out = gpu::make_texture(scene.width, scene.height, GL_R32F);
  gpu::MultiContourPass pass;
  pass.run(c.lit_texture, c.inputs, c.p, out, c.covered);
  Image own_pass = gpu::download_texture(out, 1);
  ComposeStageInputs k(scene, ref);
  gpu::Texture color = gpu::make_texture(scene.width, scene.height, GL_RGBA8);
  gpu::Texture in_compose = gpu::make_texture(scene.width, scene.height, GL_R32F);
  gpu::ComposePass().run(pass.prepare(c.lit_texture, c.inputs, c.p), k.gpu_inputs(), scene.params.get<ComposeParams>(),
                         color, {0, 0, scene.width, scene.height}, &in_compose);
  Image drawn_in_compose = gpu::download_texture(in_compose, 1);
  gpu::Context::get().check_errors("multi_contour parity");
  Image ref_out = c.reference_darkness();
  const char* note = "both fed the reference lit contours and the same offset grids and contour texture; bilinear lookups";
  return {compared("multi_contour", ref_out, own_pass, kSampledTolerance, nullptr, note),
          compared("multi_contour.in_compose", ref_out, drawn_in_compose, kSampledTolerance, nullptr,
                   std::string(note) + "; drawn by the composition pass (a frame's way)")};
}

// Composition of the reference's contour darkness d (standing in for D_c), then of
// multiple contours drawn in the composition pass itself (a frame's way).
std::vector<StageParity> compose_parity(const Scene& scene, const GBuffer& ref) {
  Image contours = reference::contour_darkness(ref, scene.params.get<EdgeDetectParams>());
  ComposeStageInputs k(scene, ref);
  auto p = scene.params.get<ComposeParams>();
  gpu::Texture c = gpu::upload_texture(contours, GL_R32F);
  gpu::Texture out = gpu::make_texture(scene.width, scene.height, GL_RGBA8);
  // Where the contour stand-in can differ from 0 (the whole window in formula mode).
  PixelRect inside = contour_rect(scene, preprocess(scene, {"distortion"}).offset_grids);
  gpu::ComposePass().run(c, true, k.gpu_inputs(), p, out, inside);
  Image alone = gpu::download_texture(out, 3);
  ContourStageInputs m(scene, ref);
  gpu::MultiContourPass multi;
  gpu::ComposePass().run(multi.prepare(m.lit_texture, m.inputs, m.p), k.gpu_inputs(), p, out, m.covered, nullptr);
  Image with_contours = gpu::download_texture(out, 3);
  gpu::Context::get().check_errors("compose parity");
  return {compared("compose", reference::compose(contours, k.interior, k.paper, p), alone, parity_tolerance::kByte, nullptr,
                   "both fed the reference contours, an interior and the paper color; 8-bit target"),
          compared("compose.contours_drawn_in", reference::compose(m.reference_darkness(), k.interior, k.paper, p),
                   with_contours, parity_tolerance::kByte, nullptr,
                   "multiple contours drawn in the pass from the reference lit contours, an interior, the paper color; "
                   "8-bit target")};
}

// SPEC 2.6-2.8 alone (tone to layer, rotated textures, 3-way blending), then with cross
// hatching (2.9) and the paper effect (2.10) on.
std::vector<StageParity> pencil_interior_parity(const Scene& scene, const GBuffer&) {
  Preprocessed pre = preprocess(scene, {"curvature", "pencil_textures", "paper"});
  GBuffer ref = reference::trace_gbuffer(scene, scene.width, scene.height, pre.curvature);
  auto ip = scene.params.get<InteriorParams>();
  float mu_p = scene.params.get<PaperParams>().mu_p;
  Image intensity = reference::interior_intensity(ref, view_space_lights(scene), ip);
  gpu::GBufferTargets g = gpu::upload_gbuffer(ref);
  gpu::TriangleAngles angles = gpu::triangle_angles_from(ref);
  gpu::Texture stack = gpu::upload_texture_3d(pre.pencil_stack, GL_R32F);
  gpu::Texture normal = gpu::upload_texture(pre.paper.normal, GL_RGBA32F);
  gpu::Texture out = gpu::make_texture(scene.width, scene.height, GL_R32F);
  gpu::Texture gpu_intensity = gpu::make_texture(scene.width, scene.height, GL_R32F);
  gpu::PencilInteriorPass pass;
  std::vector<StageParity> results;
  for (auto [name, options] : {std::pair{"pencil_interior.blend", InteriorOptions{false, false}},
                               std::pair{"pencil_interior.hatch_paper", InteriorOptions{true, true}}}) {
    pass.run(g, angles, view_space_lights(scene), stack, normal, options, ip, mu_p, out, &gpu_intensity, filter_rect(scene, 0));
    Image gpu_out = gpu::download_texture(out, 1);
    gpu::Context::get().check_errors("pencil_interior parity");
    Image ref_out = reference::interior_darkness(ref, intensity, pre.pencil_stack, pre.paper.normal, options, ip, mu_p);
    results.push_back(compared(name, ref_out, gpu_out, kSampledTolerance, nullptr,
                               "both fed the reference G-buffer (the GPU its corner angles as triangle records), pencil stack, paper; "
                               "the GPU shades its own I' (second output)"));
  }
  return results;
}

StageParity interior_intensity_parity(const Scene& scene, const GBuffer& ref) {
  auto p = scene.params.get<InteriorParams>();
  std::vector<Light> lights = view_space_lights(scene);
  gpu::GBufferTargets inputs = gpu::upload_gbuffer(ref);
  gpu::Texture white = gpu::upload_texture_3d({Image(1, 1, 1, 1.0f), Image(1, 1, 1, 1.0f)}, GL_R32F);
  gpu::Texture darkness = gpu::make_texture(scene.width, scene.height, GL_R32F);
  gpu::Texture out = gpu::make_texture(scene.width, scene.height, GL_R32F);
  gpu::PencilInteriorPass().run(inputs, gpu::triangle_angles_from(ref), lights, white, white, {}, p, 0.0f, darkness, &out, filter_rect(scene, 0));
  Image gpu_out = gpu::download_texture(out, 1);
  gpu::Context::get().check_errors("interior_intensity parity");
  return compared("interior_intensity", reference::interior_intensity(ref, lights, p), gpu_out, parity_tolerance::kFloat,
                  nullptr, "both fed the reference G-buffer; second output of the GPU's pencil_interior pass");
}

StageParity contour_light_parity(const Scene& scene, const GBuffer& ref) {
  auto p = scene.params.get<ContourLightParams>();
  std::vector<Light> lights = view_space_lights(scene);
  Image darkness = reference::contour_darkness(ref, scene.params.get<EdgeDetectParams>());
  gpu::GBufferTargets inputs = gpu::upload_gbuffer(ref);
  gpu::Texture d = gpu::make_texture(scene.width, scene.height, GL_R32F);
  gpu::Texture out = gpu::make_texture(scene.width, scene.height, GL_R32F);
  gpu::EdgeDetectPass().run(inputs, scene.params.get<EdgeDetectParams>(), lights, p, {out, &d}, filter_rect(scene, 1));
  Image gpu_out = gpu::download_texture(out, 1);
  gpu::Context::get().check_errors("contour_light parity");
  return compared("contour_light", reference::lit_contour_darkness(darkness, ref, lights, p), gpu_out,
                  parity_tolerance::kFloat, nullptr,
                  "both fed the reference G-buffer; the GPU lights its own d (second output of edge_detect)");
}

// Angles compared as (cos, sin) pairs, so that -pi and pi agree.
Image angle_vectors(const Image& theta) {
  Image v(theta.width, theta.height, 6);
  for (size_t i = 0; i < theta.pixels(); ++i)
    for (int k = 0; k < 3; ++k) {
      v.data[i * 6 + 2 * k] = std::cos(theta.data[i * 3 + k]);
      v.data[i * 6 + 2 * k + 1] = std::sin(theta.data[i * 3 + k]);
    }
  return v;
}

// SPEC 2.7's corner angles, raster vs ray on the same curvature, where both backends see
// the same triangle away from depth discontinuities.
std::vector<StageParity> texture_rotation_parity(const Scene& scene, const GBuffer&) {
  Preprocessed pre = preprocess(scene, {"curvature"});
  GBuffer ref = reference::trace_gbuffer(scene, scene.width, scene.height, pre.curvature);
  gpu::GBufferTargets targets = gpu::make_gbuffer_targets(scene.width, scene.height, GBufferFormat::RGBA32F);
  gpu::GBufferPass(scene, pre.curvature).render(scene, targets);
  GBuffer ras = gpu::download_gbuffer(targets);
  gpu::Context::get().check_errors("texture_rotation parity");
  Image mask = same_triangle(ref, ras, interior_mask(ref, ras));
  const char* note = "(cos, sin) of each corner's angle; interior pixels on the same triangle";
  return {compared("texture_rotation.theta_min", angle_vectors(ref.theta_min), angle_vectors(ras.theta_min),
                   kAngleTolerance, &mask, note),
          compared("texture_rotation.theta_max", angle_vectors(ref.theta_max), angle_vectors(ras.theta_max),
                   kAngleTolerance, &mask, note)};
}

// Whole frames (SPEC 5 "end to end"): each backend from its own G-buffer and every pass
// of the scene's effects. Pixels differ where the rasterizer and the tracer disagree on
// coverage (the band along silhouettes) and wherever that moves a contour copy or a
// stroke; the share of pixels within 2/255 is what is reported and bounded per scene.
std::vector<StageParity> end_to_end_parity(const Scene& scene, const GBuffer&) {
  Frame ref = reference::render(scene);
  Frame gpu_frame = gpu::Renderer(scene).render();
  StageParity s = compared("end_to_end", ref.color, gpu_frame.color, parity_tolerance::kByte, nullptr,
                           "whole frames, each backend from its own G-buffer");
  s.pass = s.diff.over_tolerance <= kEndToEndShare;
  return {s};
}

using ParityFn = std::function<std::vector<StageParity>(const Scene&, const GBuffer&)>;

const std::vector<std::pair<std::string, ParityFn>>& parity_table() {
  static const std::vector<std::pair<std::string, ParityFn>> table = {
      {"gbuffer", gbuffer_parity},
      {"edge_detect", [](const Scene& s, const GBuffer& g) { return std::vector{edge_parity(s, g)}; }},
      {"contour_light", [](const Scene& s, const GBuffer& g) { return std::vector{contour_light_parity(s, g)}; }},
      {"multi_contour", multi_contour_parity},
      {"texture_rotation", texture_rotation_parity},
      {"interior_intensity",
       [](const Scene& s, const GBuffer& g) { return std::vector{interior_intensity_parity(s, g)}; }},
      {"pencil_interior", pencil_interior_parity},
      {"compose", compose_parity},
      {"sketchy_enlarged", [](const Scene& s, const GBuffer&) { return sketchy_enlarged_parity(s); }},
      {"sketchy_maps", [](const Scene& s, const GBuffer&) { return sketchy_maps_parity(s); }},
      {"sketchy_composite", [](const Scene& s, const GBuffer&) { return sketchy_composite_parity(s); }},
      {"end_to_end", end_to_end_parity},
  };
  return table;
}

}  // namespace

StageParity compared(std::string name, Image ref, Image gpu, double tol, const Image* mask, std::string note) {
  StageParity s{std::move(name), compare_images(ref, gpu, tol, mask), false, std::move(ref), std::move(gpu), std::move(note)};
  s.pass = s.diff.over_tolerance == 0;
  return s;
}

Image interior_mask(const GBuffer& a, const GBuffer& b) {
  Image m(a.depth.width, a.depth.height, 1);
  for (int y = 0; y < m.height; ++y)
    for (int x = 0; x < m.width; ++x) {
      bool hit = !a.background(x, y) && a.ids.at(x, y, 0) == b.ids.at(x, y, 0);
      m.at(x, y) = hit && !near_discontinuity(a, x, y) && !near_discontinuity(b, x, y) ? 1.0f : 0.0f;
    }
  return m;
}

std::vector<std::string> parity_stages() {
  std::vector<std::string> names;
  for (const auto& [name, fn] : parity_table()) names.push_back(name);
  return names;
}

std::vector<StageParity> run_parity(const Scene& scene, const std::vector<std::string>& stages) {
  const auto known = parity_stages();
  for (const auto& s : stages)
    if (std::find(known.begin(), known.end(), s) == known.end()) {
      std::string list;
      for (const auto& k : known) list += (list.empty() ? "" : ", ") + k;
      throw std::invalid_argument("unknown stage '" + s + "' (known: " + list + ")");
    }
  gpu::Context::get();
  GBuffer ref = reference::trace_gbuffer(scene, scene.width, scene.height);
  std::vector<StageParity> out;
  for (const auto& [name, fn] : parity_table()) {
    if (!stages.empty() && std::find(stages.begin(), stages.end(), name) == stages.end()) continue;
    for (auto& s : fn(scene, ref)) out.push_back(std::move(s));
  }
  return out;
}

}  // namespace plumbago
