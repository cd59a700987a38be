// The list of every stage's parameter struct, in pipeline order. Adding a stage's
// struct here is all it takes for `plumbago params`, --set, scene files and the GLSL
// declarations to know its parameters.
#pragma once

#include "common/compose.hpp"
#include "common/contour_light.hpp"
#include "common/curvature.hpp"
#include "common/edge_detect.hpp"
#include "common/gbuffer.hpp"
#include "common/distortion.hpp"
#include "common/interior.hpp"
#include "common/noise.hpp"
#include "common/paper.hpp"
#include "common/pencil_texture.hpp"
#include "common/sketchy.hpp"

namespace plumbago {

template <class... T>
struct TypeList {};

using AllParamStructs = TypeList<CurvatureParams, PencilParams, GBufferParams, EdgeDetectParams, ContourLightParams, ContourParams,
                                 InteriorParams, PaperParams, ComposeParams, NoiseTextureParams, SketchyParams>;

}  // namespace plumbago
