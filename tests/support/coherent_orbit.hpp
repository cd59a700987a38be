// An orbit's frames with coherent silhouettes (Kalnins et al. 2003) carried as the reference
// carries them, and on the GPU the last frame's brush samples voted over this frame's runs
// and fitted there: what the coherence parity tests compare, frame after frame.
#pragma once

#include <string>
#include <vector>

#include "common/scene/animation.hpp"
#include "common/strokes/coherent_silhouettes.hpp"
#include "gpu/strokes/brush_fit.hpp"
#include "gpu/strokes/brush_votes.hpp"
#include "parity/lines.hpp"
#include "tests/support/test_scenes.hpp"

namespace plumbago::testing {

// Every coherence parameter away from its default (the tests that check both backends read
// them all).
inline const std::vector<std::string> kCoherenceSets = {
    "coherence.sample_px=5",   "coherence.search_px=9", "coherence.depth_tolerance=0.02", "coherence.jump_px=2",
    "coherence.claim_votes=3", "coherence.knot_px=24",  "coherence.scale_weight=0.5",     "coherence.distort_weight=3"};

// A frame after the first: the reference's parameters (coherent_parameters) and the GPU's
// fit of the same samples' votes, over the runs `tables` put up.
struct CoherentFrame {
  const Scene& at;
  const SceneLines& found;
  const std::vector<RunBrush>& reference;
  const gpu::RunTables& tables;
  const gpu::BrushFit& fit;
};

// Hands each frame after the first of scene `name`'s orbit of `frames` frames to `check`; each
// frame's brush samples are drawn with the reference's parameters. The coherence parameters
// are the scene's, with `sets` (stage.param=value) applied.
template <class Check>
void follow_coherent_orbit(const char* name, int frames, Check check, const std::vector<std::string>& sets = {}) {
  Scene scene = orbit_scene(name, frames);
  for (const std::string& set : sets) scene.params.set_assignment(set);
  const CoherenceParams p = scene.params.get<CoherenceParams>();
  std::vector<BrushSample> previous;
  gpu::BrushVotes votes;
  gpu::BrushFit fit;
  for (int frame = 0; frame < frames; ++frame) {
    Scene at = scene_at_frame(scene, frame);
    SceneLines found = scene_lines(at, "reference");
    std::vector<RunBrush> reference(found.visibility.runs.size());
    if (frame > 0) {
      reference = coherent_parameters(previous, at.camera, found.lines, found.visibility, p);
      gpu::UploadedRuns tables(found.lines, found.visibility);
      votes(previous, at.camera, at.width, at.height, tables.tables(), p);
      fit(votes, tables.tables(), p);
      check(CoherentFrame{at, found, reference, tables.tables(), fit});
    }
    previous = brush_samples(found.lines, found.visibility, reference, p, at.seed);
  }
}

}  // namespace plumbago::testing
