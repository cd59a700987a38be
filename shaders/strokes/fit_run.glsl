// A run's record of the coherent silhouettes' fit (shaders/strokes/brush_fit.comp Run, which
// writes it; gpu/strokes/brush_fit.cpp RunRecord): its votes, and its knots in the fit's
// knots from first_knot (fewer than 2: t = s).
struct FitRun {
  double length;
  uint first_vote, vote_count, first_knot, knot_count;
};
