// A run's record of the coherent silhouettes' fit (shaders/strokes/brush_fit.comp Run, which
// writes it; gpu/strokes/brush_fit.hpp FitRunRecord): its votes, its knots in the fit's
// knots from first_knot (fewer than 2: t = s), and its brush path (strokes/brush_path.glsl).
struct FitRun {
  double length;
  uint first_vote, vote_count, first_knot, knot_count, path, pad;
};
