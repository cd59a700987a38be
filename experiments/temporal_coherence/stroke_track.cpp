#include "experiments/temporal_coherence/stroke_track.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "common/util/random.hpp"
#include "common/util/segment_grid.hpp"

namespace plumbago::temporal_coherence {

namespace {

// TrackedRun::curve of a path: a hash of its object, kind, key and surface points.
uint64_t curve_of(const WindowPath& path) {
  std::string bytes;
  auto append = [&](const auto& v) { bytes.append(reinterpret_cast<const char*>(&v), sizeof v); };
  append(path.object), append(path.kind), append(path.key);
  for (const SurfacePoint& p : path.surface) append(p.face), append(p.bary);
  return named_seed(0, bytes);
}

}  // namespace

FrameStrokes frame_strokes(const Camera& camera, int width, int height, const WindowLines& lines,
                           const Visibility& visibility, const std::vector<RunStroke>& strokes) {
  WindowProjection project(camera, width, height);
  FrameStrokes out{camera, width, height, {}, {}};
  for (const WindowPath& path : lines.paths) out.curves.insert(curve_of(path));
  for (size_t i = 0; i < visibility.runs.size(); ++i) {
    const VisibleRun& run = visibility.runs[i];
    const BaseStrokeSamples& b = strokes.at(i).samples;
    if (b.samples.size() < 2 || !(b.length_px > 0)) continue;  // draws nothing
    const WindowPath& path = lines.paths[run.path];
    TrackedRun tracked{path.kind, path.object, curve_of(path), b.length_px, b.closed, {}};
    double path_per_spline = (run.s1 - run.s0) / b.length_px;
    for (const StrokeSample& q : b.samples) {
      glm::dvec3 world = world_at(path, run.s0 + q.s * path_per_spline);
      glm::dvec3 seen = project(world);
      tracked.samples.push_back({world, glm::dvec2(seen), seen.z, q.t, q.width, q.alpha, q.position - q.base, q.s});
    }
    out.runs.push_back(std::move(tracked));
  }
  return out;
}

namespace {

// A piece of a stroke: from sample k to k + 1 of run `run` (a loop's last sample is its
// first again, at s = length, so its pieces close it).
struct Piece {
  size_t run, k;
};

// The pieces of a frame's strokes, and a grid of `cell` px over its window holding them.
struct PieceGrid {
  PieceGrid(const FrameStrokes& f, double cell) : grid(f.width, f.height, cell) {
    for (size_t r = 0; r < f.runs.size(); ++r)
      for (size_t k = 0; k + 1 < f.runs[r].samples.size(); ++k) {
        grid.add(f.runs[r].samples[k].window, f.runs[r].samples[k + 1].window, uint32_t(pieces.size()));
        pieces.push_back({r, k});
      }
  }

  // Calls visit(piece) for the pieces near the box [lo, hi] (SegmentGrid::near).
  template <class Visit>
  void near(glm::dvec2 lo, glm::dvec2 hi, const Visit& visit) const {
    grid.near(lo, hi, [&](uint32_t i) { visit(pieces[i]); });
  }

  std::vector<Piece> pieces;
  SegmentGrid grid;
};

// Whether landing a beats b: nearer, or (at a point two pieces share, such as a loop's
// seam, where s = 0 and s = length meet) as near and nearer in s to the sample's own.
bool better(const Landing& a, const std::optional<Landing>& b, double own_s) {
  constexpr double kTie = 1e-9;  // px
  if (!b || a.distance_px < b->distance_px - kTie) return true;
  return a.distance_px <= b->distance_px + kTie && std::abs(a.s - own_s) < std::abs(b->s - own_s);
}

// Where `sample` of `from`, seen in `to` at window point (seen.x, seen.y) and depth seen.z,
// lands on `to`'s strokes of its curve (`same_curve`) or else of its kind and object.
std::optional<Landing> land(const FrameStrokes& to, const PieceGrid& grid, const TrackedRun& from, bool same_curve,
                            const TrackedSample& sample, glm::dvec3 seen, const MatchParams& p) {
  glm::dvec2 q(seen);
  std::optional<Landing> best;
  grid.near(q - p.radius_px, q + p.radius_px, [&](const Piece& piece) {
    const TrackedRun& run = to.runs[piece.run];
    if (same_curve ? run.curve != from.curve : run.kind != from.kind || run.object != from.object) return;
    const TrackedSample &a = run.samples[piece.k], &b = run.samples[piece.k + 1];
    auto [t, distance] = nearest_on(a.window, b.window, q);
    double depth = std::lerp(a.depth, b.depth, t);
    if (distance > p.radius_px || std::abs(depth - seen.z) > p.depth_tolerance * seen.z) return;
    Landing l{piece.run,
              std::lerp(a.s, b.s, t),
              std::lerp(a.width, b.width, t),
              std::lerp(a.alpha, b.alpha, t),
              glm::mix(a.offset, b.offset, t),
              distance};
    if (better(l, best, sample.s)) best = l;
  });
  return best;
}

}  // namespace

Landings carry(const FrameStrokes& from, const FrameStrokes& to, const MatchParams& params) {
  PieceGrid grid(to, std::max(4.0, 2 * params.radius_px));
  WindowProjection project(to.camera, to.width, to.height);
  Landings out;
  for (const TrackedRun& run : from.runs) {
    out.emplace_back();
    bool same_curve = to.curves.count(run.curve) > 0;
    for (const TrackedSample& sample : run.samples) {
      glm::dvec3 seen = project(sample.world);
      out.back().push_back(seen.z > 0 ? land(to, grid, run, same_curve, sample, seen, params) : std::nullopt);
    }
  }
  return out;
}

}  // namespace plumbago::temporal_coherence
