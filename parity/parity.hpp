// Stage parity (docs/conventions.md), from the stage descriptors (common/core/stage.hpp): for each GPU pass
// that computes a stage (alone, or fused with others as a frame runs it), the reference
// computes the pass's declared inputs, the GPU pass gets them uploaded, both compute the
// pass's stages, and every declared output is compared with its declared tolerance and
// mask. Stages that rasterize geometry (the G-buffers, the enlarged sketchy objects) are
// compared raster against ray where both see the same surface. `end_to_end` compares
// whole frames, each backend from its own G-buffer.
#pragma once

#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "common/scene/scene.hpp"
#include "common/util/image_compare.hpp"

namespace plumbago {

struct StageParity {
  std::string name;  // "<stage>.<output>", and " in <a+b>" for a fused pass's
  ImageDiff diff;
  bool pass = false;
  Image reference, gpu;  // the two outputs (the heat map is made on request; angles are compared as (cos, sin))
  std::string note;      // what was excluded, and why the tolerance is what it is
  size_t bounded = 0;    // pixels where a derived per-pixel bound is over the tolerance (doubles what it allows)
};

// The stage registry as a program starts: the descriptors and their parameter structs
// (common/core/stage.hpp), and a frame implementation of every frame stage on both backends.
// Throws std::logic_error saying what is wrong.
void check_stage_registry();

// One comparison; it passes when no pixel (within `mask`, if given) is over `tolerance`.
StageParity compared(std::string name, Image reference, Image gpu, double tolerance, const Image* mask,
                     std::string note);

// What `run_parity` knows: every frame stage, in registry order, then "end_to_end".
std::vector<std::string> parity_stages();

// Runs the parity of each named stage (all when empty) on `scene`. A stage the scene's
// effects do not run is checked with the effect that runs it added; one no effect can
// run there (a sketchy stage without sketchy objects) gives nothing. Throws
// std::invalid_argument naming an unknown stage.
std::vector<StageParity> run_parity(const Scene& scene, const std::vector<std::string>& stages = {});

// What `plumbago compare --json` prints of `results`: {pass (all passed), renderer (the
// GPU's), stages: [{name, pass, max_abs, rmse, over_tolerance, tolerance,
// compared_pixels, bounded_pixels, note}]}.
nlohmann::json parity_report(const std::vector<StageParity>& results);

// run_parity in steps, for a caller whose GL thread must stay free while the reference
// computes (plumbago view): the reference half of each step runs on any thread (CPU
// only), the GPU half and the comparison on the thread whose GPU context is current.
// Each step gives what run_parity gives for it, in the same order.
class ParityRun {
 public:
  // Checks the stage names (std::invalid_argument) and plans the steps; runs nothing.
  explicit ParityRun(const Scene& scene, const std::vector<std::string>& stages = {});
  ~ParityRun();
  ParityRun(const ParityRun&) = delete;
  ParityRun& operator=(const ParityRun&) = delete;

  size_t size() const { return steps_.size(); }
  void reference(size_t step);  // in order; one at a time
  // After reference(step), on the GPU context's thread; frees the step's data.
  std::vector<StageParity> gpu(size_t step);

 private:
  struct Step;
  class References;
  std::vector<std::unique_ptr<Step>> steps_;
  std::unique_ptr<References> references_;
};

// Pixels where both G-buffers hit the same object and no pixel of the 3x3 neighborhood
// (in either) lies across a depth discontinuity: another object, the background, or a
// linear-depth jump over 1%. 1 = interior, 0 = band or background.
struct GBuffer;
Image interior_mask(const GBuffer& a, const GBuffer& b);

}  // namespace plumbago
