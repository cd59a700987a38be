// Preprocessing (Lee et al. 2006, §4.2, §5) shared by both backends: made once per scene and parameter
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
  std::vector<Image> offset_grids;        // "distortion": one RG grid per contour copy (Lee et al. 2006, §4.2, Eq. 2)
  Image contour_texture;                  // "contour_texture": pencil layer contour.texture_layer (Lee et al. 2006,
                                          // §5.1, Eq. 3-4)
  std::vector<glm::vec2> texture_shifts;  // o_k of Lee et al. 2006, §4.2-4.3
  std::vector<Curvature> curvature;       // "curvature": one per scene object (Lee et al. 2006, §5.3; Alliez et al.
                                          // 2003)
  std::vector<Image> pencil_stack;        // "pencil_textures": the tone stack (Lee et al. 2006, §5.1, Eq. 3-4)
  Paper paper;                            // "paper" (Lee et al. 2006, §5.5)
  SketchyNoise sketchy_noise;             // "sketchy_noise" (Nienhaus & Döllner 2004, §3.2; §3.4, §4)
  std::vector<PassTime> ran;              // the steps that ran, with their times
};

Preprocessed preprocess(const Scene& scene, const std::vector<std::string>& passes);

}  // namespace plumbago
