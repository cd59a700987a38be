// Interior intensity and brightness (Lee §3, §5.2), and the parameters of the
// whole interior (Lee et al. 2006, §3, §5.2-5.4). The G-buffer's Gouraud channel reads them.
//   I = clamp(k_a + k_d sum_lights intensity max(0, n.L)),  I' = sqrt(I) (brightness_sqrt)
#pragma once

#include <glm/glm.hpp>
#include <vector>

#include "common/core/stage.hpp"
#include "common/scene/gbuffer.hpp"
#include "common/scene/scene.hpp"

namespace plumbago {

enum class InteriorShading { Gouraud, Phong };
enum class InteriorBlend { ThreeWay, NearestCorner };

struct InteriorParams {
  static constexpr const char* stage = "interior";
  float ambient, diffuse;
  InteriorShading shading;
  InteriorBlend blend;
  bool brightness_sqrt;
  float texture_scale, min_projected, crosshatch_below, crosshatch_band;
  template <class V>
  void visit(V& v) {
    v.real(ambient, "ambient", 0.1, 0.0, 1.0, "ambient term k_a of the interior intensity (Lee et al. 2006, §3, §5.2)");
    v.real(diffuse, "diffuse", 0.9, 0.0, 4.0,
           "diffuse weight k_d of the interior intensity (Lee et al. 2006, §3, §5.2)");
    v.choice(shading, "shading", InteriorShading::Gouraud, {"gouraud", "phong"},
             "interior intensity per vertex (Lee) or per pixel");
    v.choice(blend, "blend", InteriorBlend::ThreeWay, {"three_way", "nearest_corner"},
             "three_way: the corners' rotated textures weighted by the barycentrics (Lee et al. 2006, §5.4); "
             "nearest_corner: "
             "only the texture of the corner with the largest weight (the ablation of Lee Fig. 6)");
    v.boolean(brightness_sqrt, "brightness_sqrt", true,
              "brightness adjustment I' = sqrt(I) (Lee §5.2; Pacheco turns it off)");
    v.real(texture_scale, "texture_scale", 1.0, 0.05, 64.0,
           "window pixels per pencil-texture texel (Lee et al. 2006, "
           "§5.3)");
    v.real(min_projected, "min_projected", 0.05, 0.0, 1.0,
           "a projected curvature direction shorter than this (relative) is not trusted (Lee et al. 2006, §5.3)");
    v.real(crosshatch_below, "crosshatch_below", 0.45, 0.0, 1.0,
           "T: cross hatching where I' < T (Lee et al. 2006, "
           "§5.4, Fig. 7)");
    v.real(crosshatch_band, "crosshatch_band", 0.1, 0.0, 1.0, "width of the smoothstep that fades hatching in");
  }
};

// I = clamp(k_a + k_d sum_lights intensity * max(0, n.L)) (Lee et al. 2006, §3, §5.2); unit light
// directions in the space of n (common/scene/lights.hpp).
float lambert_intensity(glm::vec3 n, const std::vector<Light>& unit_lights, const InteriorParams& p);

// Brightness adjustment I' = sqrt(I) when p.brightness_sqrt (Lee §5.2).
float adjusted_brightness(float intensity, const InteriorParams& p);

inline constexpr Buffer kIntensity{"interior_intensity.intensity"};  // I'

struct InteriorIntensityStage {
  using Params = TypeList<InteriorParams>;
  static bool gouraud(const StageConfig& c) {
    return c.params.get<InteriorParams>().shading == InteriorShading::Gouraud;
  }
  static bool phong(const StageConfig& c) { return !gouraud(c); }
  static StageDesc describe() {
    return {.name = "interior_intensity",
            .kind = StageKind::Frame,
            .doc = "interior intensity and brightness (Lee et al. 2006, §3, §5.2)",
            .params = {"interior"},
            .inputs = {{.handle = kGBuffer.ids},
                       {.handle = kGBuffer.gouraud, .used = gouraud},
                       {.handle = kGBuffer.normal, .used = phong}},
            .outputs = {{.handle = kIntensity,
                         .doc = "I'; 1 on the background",
                         .tolerance = tolerance::kFloat,
                         .tolerance_why = "fed the same G-buffer; float target"}}};
  }
};

}  // namespace plumbago
