// Preprocessing (SPEC §1) shared by both backends: made once per scene and parameter
// set on the CPU, handed unchanged to the reference and uploaded to the GPU. Only the
// steps the scene's passes name are run (common/core/passes.hpp).
#pragma once

#include <string>
#include <vector>

#include "common/curvature/curvature.hpp"
#include "common/core/frame.hpp"
#include "common/pencil/paper.hpp"
#include "common/scene/scene.hpp"
#include "common/sketchy/sketchy.hpp"

namespace plumbago {

struct Preprocessed {
  std::vector<Image> offset_grids;        // "distortion": one RG grid per contour copy (SPEC 1.4)
  Image contour_texture;                  // "contour_texture": pencil layer contour.texture_layer (SPEC 1.2)
  std::vector<glm::vec2> texture_shifts;  // o_k of SPEC 2.4
  std::vector<Curvature> curvature;       // "curvature": one per scene object (SPEC 1.1)
  std::vector<Image> pencil_stack;        // "pencil_textures": the tone stack (SPEC 1.2)
  Paper paper;                            // "paper" (SPEC 1.3)
  SketchyNoise sketchy_noise;             // "sketchy_noise" (SPEC 3.2, 3.5)
  std::vector<PassTime> ran;              // the steps that ran, with their times
};

Preprocessed preprocess(const Scene& scene, const std::vector<std::string>& passes);

}  // namespace plumbago
