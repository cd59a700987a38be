// A visible run's window polyline, point by point (common/strokes/visibility.cpp run_along),
// after strokes/window_paths.glsl: a whole closed path's points; else the point at s0, the
// path's points strictly between s0 and s1 (a closed path's past its seam on their next
// lap), and the point at s1. Each with its linear view depth: a path point's own, the ends'
// perspective-correct (depth_at).
struct RunWalk {
  Run r;
  Path p;
  uint lap, k, stage;  // stage 0: the start; 1: the path's points; 2: the end; 3: done
};

struct RunPoint {
  dvec2 window;
  double depth;
};

const uint kWholeRun = 1u;  // Run.flags: the whole closed path

// The arc length of path point k on lap `lap` (a closed path's second lap runs past its seam).
double lap_s(Path p, uint lap, uint k) { return point(p, k).s + double(lap) * p.length_px; }

// The first point of `lap` past s (the path's point count if none): the points' arc lengths
// only grow, so the run's points are those from here up to s1.
uint first_past(Path p, uint lap, double s) {
  uint lo = 0u, hi = p.points;
  while (lo < hi) {
    uint mid = (lo + hi) / 2u;
    if (lap_s(p, lap, mid) > s) hi = mid; else lo = mid + 1u;
  }
  return lo;
}

// A run's walk starts at its first point; past s0 by a binary search, so that it costs the
// run's points, not its path's.
RunWalk start_run_walk(Run r, Path p) {
  if ((r.flags & kWholeRun) != 0u) return RunWalk(r, p, 0u, 0u, 1u);
  uint k = first_past(p, 0u, r.s0);
  if (k < p.points || !is_closed(p)) return RunWalk(r, p, 0u, k, 0u);
  return RunWalk(r, p, 1u, first_past(p, 1u, r.s0), 0u);
}

// The walk's next point; false after the last.
bool next_run_point(inout RunWalk w, out RunPoint q) {
  bool whole = (w.r.flags & kWholeRun) != 0u;
  if (w.stage == 0u) {
    w.stage = 1u;
    q = RunPoint(window_at(w.p, w.r.s0), depth_at(w.p, w.r.s0));
    return true;
  }
  while (w.stage == 1u) {
    if (w.k == w.p.points) {
      w.k = 0u, ++w.lap;
      if (whole || w.lap == (is_closed(w.p) ? 2u : 1u)) w.stage = whole ? 3u : 2u;
      continue;
    }
    Point at = point(w.p, w.k);
    if (!whole && lap_s(w.p, w.lap, w.k) >= w.r.s1) {
      w.stage = 2u;
      break;
    }
    ++w.k;
    q = RunPoint(at.window, at.depth);
    return true;
  }
  if (w.stage != 2u) return false;
  w.stage = 3u;
  q = RunPoint(window_at(w.p, w.r.s1), depth_at(w.p, w.r.s1));
  return true;
}
