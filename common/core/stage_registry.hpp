// The registry: every stage, once, in the order they run (each after the stages whose
// outputs it reads). Adding a stage is adding its header and its type here, one line
// each; `plumbago params`, --set, scene files, the GLSL declarations, the pass table,
// the effects, the dumps and the parity runner follow from its descriptor
// (common/core/stage.hpp).
#pragma once

#include "common/curvature/curvature.hpp"
#include "common/pencil/compose.hpp"
#include "common/pencil/contour_light.hpp"
#include "common/pencil/contour_texture.hpp"
#include "common/pencil/distortion.hpp"
#include "common/pencil/edge_detect.hpp"
#include "common/pencil/interior_intensity.hpp"
#include "common/pencil/multi_contour.hpp"
#include "common/pencil/paper.hpp"
#include "common/pencil/pencil_interior.hpp"
#include "common/pencil/pencil_textures.hpp"
#include "common/scene/gbuffer.hpp"
#include "common/sketchy/sketchy_composite.hpp"
#include "common/sketchy/sketchy_enlarged.hpp"
#include "common/sketchy/sketchy_gbuffer.hpp"
#include "common/sketchy/sketchy_maps.hpp"
#include "common/sketchy/sketchy_noise.hpp"
#include "common/strokes/basecoat.hpp"
#include "common/strokes/brush_parameters.hpp"
#include "common/strokes/crease_points.hpp"
#include "common/strokes/id_image.hpp"
#include "common/strokes/line_meshes.hpp"
#include "common/strokes/silhouette_chains.hpp"
#include "common/strokes/silhouette_paths.hpp"
#include "common/strokes/silhouette_segments.hpp"
#include "common/strokes/stroke.hpp"
#include "common/strokes/stroke_paper.hpp"
#include "common/strokes/visibility.hpp"

namespace plumbago {

// One stage a line (clang-format would pack them).
// clang-format off
using AllStages = TypeList<
    // preprocessing (Lee et al. 2006, §4.2, §5), made once per scene and parameters
    DistortionStage,
    PencilTexturesStage,
    ContourTextureStage,
    PaperStage,
    SketchyNoiseStage,
    CurvatureStage,
    LineMeshesStage,
    // the pencil pipeline (Lee et al. 2006)
    GBufferStage,
    EdgeDetectStage,
    ContourLightStage,
    InteriorIntensityStage,
    PencilInteriorStage,
    MultiContourStage,
    ComposeStage,
    // sketchy drawing (Nienhaus & Döllner 2004)
    SketchyGBufferStage,
    SketchyEnlargedStage,
    SketchyMapsStage,
    SketchyCompositeStage,
    // stroke-based rendering (Kalnins et al. 2002), over what the others drew
    BaseCoatStage,
    StrokePaperStage,
    SilhouetteSegmentsStage,
    SilhouetteChainsStage,
    SilhouettePathsStage,
    CreasePointsStage,
    IdImageStage,
    VisibilityStage,
    BrushParametersStage,
    StrokeStage>;
// clang-format on

}  // namespace plumbago
