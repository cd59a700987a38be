// The GPU's fit of coherent silhouettes (shaders/strokes/brush_fit.comp) against the
// reference's fit_brush_parameter (common/strokes/coherent_silhouettes.hpp 3.-4.), run by
// run: the same groups, sections and knots (counts and arc lengths exactly), and t within a
// stated tolerance (the normal equations are the same sums in the same order; the GPU
// solves them by a banded LDL^T, the reference by Eigen's pivoting LDLT, which round apart).
// On hard cases (jumps, reversed runs, groups inside others, single votes, votes tied at an
// end, shuffled input) and on the votes of the procedural scenes' silhouettes along an orbit.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <random>

#include "common/scene/animation.hpp"
#include "common/scene/scene.hpp"
#include "gpu/strokes/brush_fit.hpp"
#include "gpu/strokes/brush_votes.hpp"
#include "parity/lines.hpp"
#include "tests/support/coherent_orbit.hpp"
#include "tests/support/test_scenes.hpp"

namespace plumbago {
namespace {

// px of t: the two solves of the same equations round apart (measured below 1e-9 px).
constexpr double kKnotTolerance = 1e-6;

struct Tally {
  size_t runs = 0, knots = 0;
  double worst = 0;  // px of t
};

// Each run's knots from both backends.
Tally compare(const std::vector<std::vector<BrushVote>>& votes, const std::vector<double>& lengths,
              const CoherenceParams& p) {
  gpu::BrushFit fit;
  fit(votes, lengths, p);
  std::vector<RunBrush> gpu = fit.parameters();
  Tally t;
  EXPECT_EQ(gpu.size(), votes.size());
  for (size_t r = 0; r < votes.size() && r < gpu.size(); ++r) {
    RunBrush ref = fit_brush_parameter(votes[r], lengths[r], p);
    EXPECT_EQ(gpu[r].path, ref.path) << "run " << r;
    EXPECT_EQ(gpu[r].knots.size(), ref.knots.size()) << "run " << r;
    if (gpu[r].knots.size() != ref.knots.size()) continue;
    t.runs += ref.knots.empty() ? 0 : 1, t.knots += ref.knots.size();
    for (size_t k = 0; k < ref.knots.size(); ++k) {
      EXPECT_EQ(gpu[r].knots[k].x, ref.knots[k].x) << "run " << r << " knot " << k;
      EXPECT_NEAR(gpu[r].knots[k].y, ref.knots[k].y, kKnotTolerance) << "run " << r << " knot " << k;
      t.worst = std::max(t.worst, std::abs(gpu[r].knots[k].y - ref.knots[k].y));
    }
  }
  return t;
}

// t = offset + rate s.
struct Line {
  double offset, rate = 1;
  double operator()(double s) const { return offset + rate * s; }
};

// Votes of `stroke` every `step` px from s0 to s1 (by default sample_px, as the last frame's
// samples land), carrying t(s).
template <class F>
std::vector<BrushVote> votes(double s0, double s1, F t, uint32_t stroke,
                             double step = ParamSet{}.get<CoherenceParams>().sample_px) {
  std::vector<BrushVote> out;
  for (double s = s0; s <= s1; s += step) out.push_back({0, s, t(s), stroke});
  return out;
}

std::vector<BrushVote> joined(std::vector<BrushVote> a, const std::vector<BrushVote>& b) {
  a.insert(a.end(), b.begin(), b.end());
  return a;
}

class BrushFitParity : public testing::GlTest {};

TEST_F(BrushFitParity, HardCasesMatchTheReference) {
  std::vector<std::vector<BrushVote>> runs;
  std::vector<double> lengths;
  auto add = [&](std::vector<BrushVote> v, double length) { runs.push_back(std::move(v)), lengths.push_back(length); };
  auto jump = [](double s) { return s < 148 ? s : s + 250; };
  add(votes(100, 200, Line{37}, 0), 300);                                          // shifted, extended
  add(votes(0, 240, Line{500, -1}, 3), 240);                                       // reversed
  add(votes(0, 288, Line{0, 1.3}, 1), 288);                                        // stretched
  add(votes(0, 200, jump, 2), 300);                                                // a jump: two groups
  add(joined(votes(0, 96, Line{10}, 1), votes(104, 300, Line{300}, 2)), 300);      // two strokes, each its side
  add(joined(votes(0, 296, Line{0}, 1), votes(120, 136, Line{90}, 2)), 300);       // a small group in a larger span
  add(joined(votes(0, 60, Line{0}, 1, 20), votes(30, 90, Line{50}, 2, 20)), 120);  // equal sizes, overlapping
  add(votes(40, 40, Line{5}, 0), 100);                                             // one vote
  // Votes tied in s where they clamp to the run's end, two of one stroke: the order of
  // (s, stroke, t) decides which group is made first, and so claims first among equals.
  std::vector<BrushVote> tied = votes(0, 56, Line{0}, 1);
  for (uint32_t k = 0; k < 4; ++k) tied.push_back({0, 70, 100.0 + 7 * k, 4 - k / 2});
  add(tied, 70);
  std::vector<BrushVote> shuffled = joined(votes(0, 400, Line{2000, -1}, 4), votes(200, 500, Line{0}, 5, 5));
  std::shuffle(shuffled.begin(), shuffled.end(), std::mt19937(7));
  add(shuffled, 520);                       // any order
  add({}, 100);                             // no votes
  add(votes(0, 10, Line{0}, 0), 0);         // no length
  add(votes(0, 3000, Line{1e5}, 0), 3000);  // long: 63 knots, far from 0
  // Votes farther apart than 3 sample_px, each its own group, hundreds (a claim each where
  // one vote claims): the claims are searched, not walked, so that the fit's loops stay
  // within what llvmpipe runs (65535 iterations a shader batch, all loops together).
  add(votes(0, 3000, Line{7}, 0, 4 * ParamSet{}.get<CoherenceParams>().sample_px), 3000);
  for (int claim_votes : {2, 1}) {
    CoherenceParams p = ParamSet{}.get<CoherenceParams>();
    p.claim_votes = claim_votes;
    Tally t = compare(runs, lengths, p);
    EXPECT_GE(t.knots, 80u);
    std::printf("brush fit, hard cases (a claim %d votes): %zu knots in %zu runs, t within %.3g px\n", claim_votes,
                t.knots, t.runs, t.worst);
  }
}

// The votes the silhouettes of `scene` get in frames 1 and 2 of an orbit (frame 1's from
// frame 0's arc length, frame 2's from frame 1's fitted parameters), per run; lengths.
void orbit_votes(const Scene& scene, std::vector<std::vector<BrushVote>>& runs, std::vector<double>& lengths) {
  CoherenceParams p = ParamSet{}.get<CoherenceParams>();
  std::vector<BrushSample> previous;
  for (int frame = 0; frame < 3; ++frame) {
    Scene at = scene_at_frame(scene, frame);
    SceneLines found = scene_lines(at, "reference");
    std::vector<RunBrush> fitted(found.visibility.runs.size());
    if (frame > 0) {
      std::vector<std::vector<BrushVote>> per_run(found.visibility.runs.size());
      for (const BrushVote& v : brush_votes(previous, at.camera, found.lines, found.visibility, p))
        per_run[v.run].push_back(v);
      for (size_t r = 0; r < per_run.size(); ++r) {
        const VisibleRun& run = found.visibility.runs[r];
        runs.push_back(per_run[r]), lengths.push_back(run.s1 - run.s0);
      }
      fitted = coherent_parameters(previous, at.camera, found.lines, found.visibility, p);
    }
    previous = brush_samples(found.lines, found.visibility, fitted, p, at.seed);
  }
}

TEST_F(BrushFitParity, OrbitVotesMatchTheReference) {
  for (const char* name : testing::kOrbitScenes) {
    Scene scene = testing::orbit_scene(name, 3);
    std::vector<std::vector<BrushVote>> runs;
    std::vector<double> lengths;
    orbit_votes(scene, runs, lengths);
    size_t voted = std::count_if(runs.begin(), runs.end(), [](const auto& v) { return !v.empty(); });
    ASSERT_GT(voted, 0u) << name;
    Tally t = compare(runs, lengths, ParamSet{}.get<CoherenceParams>());
    std::printf("brush fit, %s orbit: %zu runs voted for, %zu knots in %zu runs, t within %.3g px\n", name, voted,
                t.knots, t.runs, t.worst);
  }
}

// The whole of a frame's coherence on the GPU but its brush samples: the last frame's samples
// vote over the runs on the GPU (gpu/strokes/brush_votes.hpp), the votes are bucketed by run
// there and fitted: each run's knots as coherent_parameters gives them.
// The GPU's fit of its own votes along scene `name`'s orbit against the reference's, with the
// coherence parameters `sets` (stage.param=value).
void fit_of_gpu_votes(const char* name, const std::vector<std::string>& sets) {
  Tally t;
  testing::follow_coherent_orbit(
      name, 3,
      [&](const testing::CoherentFrame& f) {
        std::vector<RunBrush> gpu = f.fit.parameters();
        const std::vector<RunBrush>& ref = f.reference;
        ASSERT_EQ(gpu.size(), ref.size()) << name;
        for (size_t r = 0; r < ref.size(); ++r) {
          EXPECT_EQ(gpu[r].path, ref[r].path) << name << " run " << r;
          const BrushParameter &g = gpu[r].knots, &k = ref[r].knots;
          ASSERT_EQ(g.size(), k.size()) << name << " run " << r;
          t.runs += k.empty() ? 0 : 1, t.knots += k.size();
          for (size_t i = 0; i < k.size(); ++i) {
            EXPECT_EQ(g[i].x, k[i].x) << name << " run " << r << " knot " << i;
            EXPECT_NEAR(g[i].y, k[i].y, kKnotTolerance) << name << " run " << r << " knot " << i;
            t.worst = std::max(t.worst, std::abs(g[i].y - k[i].y));
          }
        }
      },
      sets);
  EXPECT_GT(t.runs, 2u) << name;
  std::printf(
      "brush fit of the GPU's votes, %s orbit (%s coherence parameters): %zu knots in %zu runs, t within %.3g px\n",
      name, sets.empty() ? "default" : "changed", t.knots, t.runs, t.worst);
}

// With the default coherence parameters, and with each away from its default.
TEST_F(BrushFitParity, VotesLeftOnTheGpuFitAsTheReference) {
  for (bool defaults : {true, false})
    for (const char* name : testing::kOrbitScenes)
      fit_of_gpu_votes(name, defaults ? std::vector<std::string>{} : testing::kCoherenceSets);
}

}  // namespace
}  // namespace plumbago
