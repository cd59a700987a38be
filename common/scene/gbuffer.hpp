// The G-buffer (docs/stages.md, gbuffer), written alike by the rasterizer (gpu/scene/gbuffer.cpp) and the
// Embree tracer (reference/scene/gbuffer.cpp), from the same world-space geometry.
#pragma once

#include <vector>

#include "common/core/stage.hpp"
#include "common/curvature/curvature.hpp"
#include "common/scene/scene.hpp"
#include "common/util/image.hpp"

namespace plumbago {

enum class GBufferFormat { RGBA32F, RGBA16F, RGBA8 };

struct GBufferParams {
  static constexpr const char* stage = "gbuffer";
  GBufferFormat normal_format;
  template <class V>
  void visit(V& v) {
    v.choice(normal_format, "normal_format", GBufferFormat::RGBA32F, {"rgba32f", "rgba16f", "rgba8"},
             "storage of the GPU normal targets (the reference is always float)");
  }
};

struct GBuffer {
  Image normal;       // 3 ch: unit view-space shading normal; 0 for background
  Image face_normal;  // 3 ch: unit view-space geometric normal; 0 for background
  Image depth;        // 1 ch: linear view depth d = -z_view; `far` for background
  ImageU32 ids;       // 2 ch: object index + 1 (0 = background), triangle index in its mesh
  Image bary;         // 3 ch: barycentric coordinates (w0, w1, w2); 0 for background
  Image gouraud;      // 1 ch: interpolated Gouraud intensity (Lee et al. 2006, §3, §5.2); 1 for background
  Image theta_min;    // 3 ch: window-space angle of each corner's min-curvature direction (Lee et al. 2006, §5.3)
  Image theta_max;    // 3 ch: the same for the max-curvature direction; both 0 without curvature
  float near = 0, far = 1;

  bool background(int x, int y) const { return ids.at(x, y, 0) == 0; }
};

// One object's geometry in world space, shared by both backends so that they rasterize
// and trace the same floats.
struct WorldObject {
  std::vector<glm::vec3> positions;  // world space
  std::vector<glm::vec3> normals;    // world space, unit (face normals when flat)
  std::vector<glm::uvec3> triangles;
  std::vector<float> gouraud;           // per vertex, Lee et al. 2006, §3, §5.2
  std::vector<glm::vec3> d_min, d_max;  // world space, unit; empty without curvature
  bool flat = false;
};

// `curvature` holds one entry per scene object, or nothing (no texture rotation).
std::vector<WorldObject> world_geometry(const Scene& scene, const std::vector<Curvature>& curvature = {});

// The relative step of linear view depth between neighbouring pixels that makes a depth
// discontinuity: the G-buffer's parity leaves out the band along one (parity/parity.cpp).
constexpr float kDepthJump = 0.01f;

// Unit geometric normal of triangle t, normalize(cross(p1 - p0, p2 - p0)); (0,0,1) for a
// zero-area triangle, never NaN.
glm::vec3 face_normal(const WorldObject& obj, size_t t);

// Normalized depth z = (d - near) / (far - near): 1 for background (docs/conventions.md).
Image normalized_depth(const GBuffer& g);

// The channels of a G-buffer as outputs of a stage (dumps hold the normalized depth), each
// saying how parity compares raster against ray (docs/conventions.md); the corner angles of Lee et al. 2006, §5.3
// `with_angles`.
std::vector<Output> gbuffer_outputs(const GBufferSlot& g, bool with_angles);

inline constexpr GBufferSlot kGBuffer{"gbuffer",           {"gbuffer.normal"},    {"gbuffer.face_normal"},
                                      {"gbuffer.depth"},   {"gbuffer.ids"},       {"gbuffer.bary"},
                                      {"gbuffer.gouraud"}, {"gbuffer.theta_min"}, {"gbuffer.theta_max"}};

struct GBufferStage {
  using Params = TypeList<GBufferParams>;
  static StageDesc describe() {
    return {.name = "gbuffer",
            .kind = StageKind::Frame,
            .doc = "G-buffer: normals, depth, ids, barycentrics, Gouraud (docs/conventions.md)",
            .params = {"gbuffer", "interior"},
            .inputs = {{.handle = kCurvature, .used = when::effect_interior}},
            .outputs = gbuffer_outputs(kGBuffer, true)};
  }
};

}  // namespace plumbago
