// A run's brush path (Kalnins et al. 2003; common/strokes/coherent_silhouettes.hpp 5.): the
// fit's where it made one, else a new one keyed by the run's Markov walk
// (common/strokes/stroke.cpp brush_path_key). The includer declares run_rows[] (Run, of
// strokes/window_paths.glsl) and includes util/random.glsl.

const uint kStampStart = 1u, kOffsetWalk = 2u;  // common/strokes/stroke.hpp RunStream
const uint kNewBrushPath = 0xffffffffu;

// The run's place among its path's runs (common/strokes/stroke.cpp run_ordinals): a path's
// runs are listed together, in order.
uint ordinal(uint run) {
  uint path = run_rows[run].path, lo = 0u, hi = run;
  while (lo < hi) {
    uint mid = (lo + hi) / 2u;
    if (run_rows[mid].path < path) lo = mid + 1u; else hi = mid;
  }
  return run - lo;
}

uint brush_path_key(uint fitted, uint seed, uint path_key, uint run) {
  return fitted != kNewBrushPath ? fitted : stream_key(seed, path_key, ordinal(run), kOffsetWalk);
}
