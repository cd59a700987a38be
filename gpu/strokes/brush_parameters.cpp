// The brush parameters of coherent silhouettes on the GPU: see gpu/strokes/brush_parameters.hpp.
#include "gpu/strokes/brush_parameters.hpp"

#include <optional>

#include "common/strokes/brush_parameters.hpp"

namespace plumbago::gpu {

namespace {

class BrushParametersPass : public GpuPass {
 public:
  explicit BrushParametersPass(GpuFrame&) {}

  void run(GpuFrame& f) override {
    // A frame that follows none and that none may follow (a still scene, not the viewer) has
    // t = s and leaves nothing to carry: no work, and the stroke pass draws arc length.
    const bool follows = f.follows_last() && carried_;
    carried_ = follows || f.may_be_followed();
    if (!carried_) {
      f.withhold(kBrushFit), f.withhold(kGpuBrushSamples);
      return;
    }
    const RunTables* tables = f.get(maybe(kRunTables));
    std::optional<UploadedRuns> uploaded;  // where visibility ran elsewhere
    if (!tables) tables = &uploaded.emplace(f.get(kWindowLines), f.get(kVisibleRuns)).tables();
    const Camera& camera = f.scene.camera;
    const int width = f.scene.width, height = f.scene.height;
    const auto p = f.params<CoherenceParams>();
    // The samples the last frame left vote where this frame follows it; else none do (t = s).
    if (follows)
      votes_(samples_, camera, width, height, *tables, p);
    else
      votes_(std::vector<BrushSample>{}, camera, width, height, *tables, p);
    fit_(votes_, *tables, p);
    samples_(*tables, camera, width, height, &fit_, p, f.scene.seed);
    f.put(kBrushFit, fit_);
    f.put(kGpuBrushSamples, samples_);
  }

 private:
  BrushVotes votes_;
  BrushFit fit_;
  BrushSamples samples_;
  bool carried_ = false;  // whether samples_ hold the last frame's
};

}  // namespace

PLUMBAGO_GPU_PASS(brush_parameters, {{"brush_parameters"}, {}, make_pass<BrushParametersPass>, Probe::Compute});

}  // namespace plumbago::gpu
