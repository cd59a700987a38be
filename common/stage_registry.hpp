// The registry: every stage, once, in the order they run (each after the stages whose
// outputs it reads). Adding a stage is adding its header and its type here, one line
// each; `plumbago params`, --set, scene files, the GLSL declarations, the pass table,
// the effects, the dumps and the parity runner follow from its descriptor
// (common/stage.hpp).
#pragma once

#include "common/basecoat.hpp"
#include "common/compose.hpp"
#include "common/contour_light.hpp"
#include "common/contour_texture.hpp"
#include "common/curvature.hpp"
#include "common/distortion.hpp"
#include "common/edge_detect.hpp"
#include "common/gbuffer.hpp"
#include "common/id_image.hpp"
#include "common/interior_intensity.hpp"
#include "common/multi_contour.hpp"
#include "common/paper.hpp"
#include "common/pencil_interior.hpp"
#include "common/pencil_textures.hpp"
#include "common/sketchy_composite.hpp"
#include "common/sketchy_enlarged.hpp"
#include "common/sketchy_gbuffer.hpp"
#include "common/sketchy_maps.hpp"
#include "common/sketchy_noise.hpp"
#include "common/stroke.hpp"
#include "common/stroke_paper.hpp"
#include "common/visibility.hpp"

namespace plumbago {

using AllStages = TypeList<
    // preprocessing (SPEC 1), made once per scene and parameters
    DistortionStage,
    PencilTexturesStage,
    ContourTextureStage,
    PaperStage,
    SketchyNoiseStage,
    CurvatureStage,
    // the pencil pipeline (SPEC 2)
    GBufferStage,
    EdgeDetectStage,
    ContourLightStage,
    InteriorIntensityStage,
    PencilInteriorStage,
    MultiContourStage,
    ComposeStage,
    // sketchy drawing (SPEC 3)
    SketchyGBufferStage,
    SketchyEnlargedStage,
    SketchyMapsStage,
    SketchyCompositeStage,
    // stroke-based rendering (SPEC 4), over what the others drew
    BaseCoatStage,
    StrokePaperStage,
    IdImageStage,
    VisibilityStage,
    StrokeStage>;

}  // namespace plumbago
