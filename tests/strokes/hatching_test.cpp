// Hatching groups (Kalnins et al. 2002, §6): the level-of-detail rule (hysteresis, one level at a time,
// the transitions' duration), the groups' hatches (order, interpolation, refusals), the
// density as a camera approaches, and parity of the stages that draw them.
#include <gtest/gtest.h>

#include <cstdio>

#include "common/scene/animation.hpp"
#include "common/strokes/decal.hpp"
#include "common/strokes/hatching.hpp"
#include "common/strokes/strokes.hpp"
#include "gpu/strokes/decal.hpp"
#include "parity/parity.hpp"
#include "reference/strokes/decal.hpp"
#include "tests/support/parity_checks.hpp"
#include "tests/support/test_scenes.hpp"

namespace plumbago {
namespace {

HatchingParams defaults() { return ParamSet().get<HatchingParams>(); }

constexpr double kFps = 30;
const HatchLevels kStructured{{}, -3, 2};

// The states over sigma(frame), frame i at i / kFps, from settled at frame 0.
std::vector<HatchLod> replay(const std::vector<double>& sigma, const HatchLevels& levels = kStructured,
                             const HatchingParams& p = defaults()) {
  std::vector<HatchLod> out{hatch_lod_settled(sigma[0], levels, p)};
  for (size_t k = 1; k < sigma.size(); ++k) out.push_back(hatch_lod_step(out.back(), sigma[k], k / kFps, levels, p));
  return out;
}

TEST(HatchLod, SigmaBetweenTheThresholdsCausesNoTransition) {
  for (double start : {1.0, 1.7}) {  // at level 0, and at level 1 (doubled)
    std::vector<double> sigma{start};
    for (int k = 0; k < 200; ++k) sigma.push_back(k % 2 ? 1.41 : 1.59);  // t- < sigma < t+
    std::vector<HatchLod> states = replay(sigma);
    for (const HatchLod& s : states) {
      EXPECT_EQ(s.to, start == 1.0 ? 0 : 1);
      EXPECT_EQ(s.from, s.to);
    }
  }
  // Leaving the band starts one: up at t+, down below t-.
  EXPECT_EQ(replay({1.0, 1.6}).back().to, 1);
  EXPECT_EQ(replay({1.0, 1.59}).back().to, 0);
  EXPECT_EQ(replay({1.7, 1.41}).back().to, 1);
  EXPECT_EQ(replay({1.7, 1.39}).back().to, 0);
}

TEST(HatchLod, EachTransitionLastsFadeSeconds) {
  for (double fade : {0.5, 0.2}) {
    HatchingParams p = defaults();
    p.fade_s = float(fade);
    std::vector<double> sigma(60, 1.0);
    for (size_t k = 10; k < sigma.size(); ++k) sigma[k] = 1.7;
    std::vector<HatchLod> states = replay(sigma, kStructured, p);
    EXPECT_EQ(states[9].to, 0);
    ASSERT_EQ(states[10].from, 0);
    ASSERT_EQ(states[10].to, 1);
    double start = 10 / kFps, end = start + fade;
    EXPECT_DOUBLE_EQ(states[10].progress(start, p.fade_s), 0.0);
    EXPECT_NEAR(states[10].progress(start + fade / 2, p.fade_s), 0.5, 1e-12);
    EXPECT_LT(states[10].progress(end - 1e-9, p.fade_s), 1.0);
    EXPECT_DOUBLE_EQ(states[10].progress(end, p.fade_s), 1.0);
    int frames = 0;
    for (size_t k = 10; k < states.size(); ++k) frames += states[k].progress(k / kFps, p.fade_s) < 1;
    EXPECT_EQ(frames, int(std::lround(fade * kFps))) << "frames in transition, fade " << fade;
  }
}

TEST(HatchLod, OneLevelAtATimeUpToTheHighest) {
  std::vector<double> sigma{1.0};
  sigma.resize(100, 9.0);
  std::vector<HatchLod> states = replay(sigma);
  EXPECT_EQ(states[1].to, 1);
  EXPECT_EQ(states[15].to, 1);  // the first transition ends at frame 16 (0.5 s)
  EXPECT_EQ(states[16].to, 2);
  EXPECT_EQ(states.back().to, 2);  // max_level: beyond it the strokes only thicken
  EXPECT_EQ(states.back().from, 2);
}

TEST(HatchLod, SettledLevels) {
  HatchingParams p = defaults();
  EXPECT_EQ(hatch_lod_settled(1.0, kStructured, p).to, 0);
  EXPECT_EQ(hatch_lod_settled(1.5, kStructured, p).to, 0);
  EXPECT_EQ(hatch_lod_settled(3.3, kStructured, p).to, 2);
  EXPECT_EQ(hatch_lod_settled(0.3, kStructured, p).to, -2);   // below 0.7 and 0.35: halved twice
  EXPECT_EQ(hatch_lod_settled(0.01, kStructured, p).to, -3);  // at least two hatches are left
  HatchLevels free{{1.0, 2.5, 6.0}, 0, 2};
  EXPECT_EQ(hatch_lod_settled(1.99, free, p).to, 0);
  EXPECT_EQ(hatch_lod_settled(2.0, free, p).to, 1);  // 2.5 x t+ / 2
  EXPECT_EQ(hatch_lod_settled(0.1, free, p).to, 0);
  EXPECT_EQ(hatch_lod_settled(100, free, p).to, 2);
  p.t_minus = 1.9;  // above t+: counts as t+ (read literally, 1.61 would halve a doubled group again)
  EXPECT_EQ(replay({1.7, 1.61}, kStructured, p).back().to, 1);
  EXPECT_EQ(replay({1.7, 1.59}, kStructured, p).back().to, 0);
}

// A structured group of `n` (odd) horizontal hatches 20 px apart over the window of `s`, given in
// a shuffled order, every other one drawn right to left.
StrokeFile structured_file(const Scene& s, int n, int group = 0, double y0 = 60) {
  StrokeFile f;
  f.source = "hatches";
  f.camera = s.camera, f.width = s.width, f.height = s.height;
  for (int i = 0; i < n; ++i) {
    int k = (i * 2) % n;  // n odd: a permutation
    DrawnStroke h;
    h.role = StrokeRole::Hatching, h.group = group;
    double y = y0 + 20 * k;
    h.points = {{{20.0, y}, 0.5}, {{s.width / 2.0, y + 4}, 1.0}, {{s.width - 20.0, y}, 0.5}};
    if (k % 2) std::reverse(h.points.begin(), h.points.end());
    h.style = load_stroke_style("pencil");
    f.strokes.push_back(h);
  }
  return f;
}

TEST(HatchGroups, StructuredHatchesAreOrderedAndInterpolated) {
  Scene s = testing::drawn_with_strokes(testing::builtin_at("sphere", 320, 240));
  s.stroke_files = {structured_file(s, 5)};
  std::vector<HatchPolyline> hatches = hatch_polylines(s);
  const int between = 1 << kMaxHatchLevel;
  ASSERT_EQ(hatches.size(), size_t(4 * between + 1));
  for (size_t k = 0; k < hatches.size(); ++k) {
    EXPECT_DOUBLE_EQ(hatches[k].tag.position, double(k) / between);
    // Every hatch runs left to right, at its place across: y = 60 + 20 q at both ends.
    const HatchPolyline& h = hatches[k];
    EXPECT_LT(h.points.front().window.x, h.points.back().window.x);
    EXPECT_NEAR(h.points.front().window.y, 60 + 20 * h.tag.position, 1e-9);
    EXPECT_NEAR(h.points.back().window.y, 60 + 20 * h.tag.position, 1e-9);
  }
}

TEST(HatchGroups, RefusalsNameTheFileAndTheGroup) {
  Scene s = testing::builtin_at("sphere", 320, 240);
  StrokeFile a = structured_file(s, 3), b = structured_file(s, 3);
  b.source = "more_hatches";
  s.stroke_files = {a, b};
  EXPECT_THROW(
      try { hatching_groups(s); } catch (const SceneError& e) {
        EXPECT_NE(std::string(e.what()).find("more_hatches: hatching group 0: a structured group"), std::string::npos)
            << e.what();
        throw;
      },
      SceneError);
  b.strokes[0].free = true;
  s.stroke_files = {a, b};
  EXPECT_THROW(
      try { hatching_groups(s); } catch (const SceneError& e) {
        EXPECT_NE(std::string(e.what()).find("mixes free and structured"), std::string::npos) << e.what();
        throw;
      },
      SceneError);
}

// The sphere with a structured group drawn at its camera and a dolly toward it.
Scene approaching_sphere() {
  Scene s = testing::drawn_with_strokes(testing::builtin_at("sphere", 320, 240));
  s.stroke_files = {structured_file(s, 7, 0, 60)};
  s.animation = Animation{Animation::Kind::Dolly, 0.7 * glm::distance(s.camera.eye, s.camera.target), 40, kFps};
  return s;
}

// Which hatches are present (alpha > 0) at frame i, and the group's state.
struct FrameHatches {
  HatchGroupState state;
  std::vector<HatchWeight> weights;
};
FrameHatches at_frame(const Scene& path, const DecalSurface& surface, int i) {
  Scene s = scene_at_frame(path, i);
  std::vector<HatchGroupState> states = hatch_states(s, surface, s.params.get<HatchingParams>());
  return {states.at(0), hatch_weights(states, surface)};
}

TEST(Hatching, DensityFollowsTheCameraAndFramesReplayTheirPath) {
  Scene path = approaching_sphere();
  DecalSurface surface = reference::project_decals_by_rays(path);
  FrameHatches first = at_frame(path, surface, 0);
  EXPECT_NEAR(first.state.sigma, 1.0, 1e-9);  // drawn with this camera and window
  for (size_t d = 0; d < surface.size(); ++d) {
    bool drawn = surface[d].hatch.position == std::floor(surface[d].hatch.position);
    EXPECT_EQ(first.weights[d].alpha, drawn ? 1.0 : 0.0);
    EXPECT_NEAR(first.weights[d].width, 1.0, 1e-9);
  }
  int present_before = 0, transitions = 0;
  double sigma_before = 0;
  for (int i = 0; i < path.animation->frames; ++i) {
    FrameHatches f = at_frame(path, surface, i);
    int present = 0;
    for (const HatchWeight& w : f.weights) present += w.alpha > 0;
    EXPECT_GE(present, present_before) << "frame " << i;
    EXPECT_GT(f.state.sigma, sigma_before) << "frame " << i;
    transitions += f.state.lod.from != f.state.lod.to && f.state.progress < 1;
    present_before = present, sigma_before = f.state.sigma;
  }
  FrameHatches last = at_frame(path, surface, path.animation->frames - 1);
  std::printf("[hatching] sigma 1 -> %.3f, level %d, %d of %zu hatches present, %d frames in transition\n",
              last.state.sigma, last.state.lod.to, present_before, surface.size(), transitions);
  EXPECT_GT(last.state.sigma, 2.0);
  EXPECT_EQ(last.state.lod.to, 2);
  EXPECT_GT(transitions, 0);
  // Frame 30 reached from frame 12's scene replays the path from its start.
  Scene twelve = scene_at_frame(path, 12);
  FrameHatches direct = at_frame(path, surface, 30), via = at_frame(twelve, surface, 30);
  EXPECT_EQ(direct.state.lod.to, via.state.lod.to);
  EXPECT_DOUBLE_EQ(direct.state.progress, via.state.progress);
  EXPECT_DOUBLE_EQ(direct.state.sigma, via.state.sigma);
}

TEST(Hatching, FreeGroupsShowTheLevelsDrawnFromCloser) {
  Scene s = testing::drawn_with_strokes(testing::builtin_at("sphere", 320, 240));
  StrokeFile far = structured_file(s, 3, 4), near = structured_file(s, 5, 4, 70);
  Scene closer = s;
  closer.camera.eye = s.camera.target + 0.4f * (s.camera.eye - s.camera.target);
  near.camera = closer.camera;
  for (StrokeFile* f : {&far, &near})
    for (DrawnStroke& h : f->strokes) h.free = true;
  s.stroke_files = closer.stroke_files = {far, near};
  DecalSurface surface = reference::project_decals_by_rays(s);
  for (const Scene* view : {&s, &closer}) {
    std::vector<HatchGroupState> states = hatch_states(*view, surface, defaults());
    ASSERT_EQ(states.size(), 1u);
    EXPECT_TRUE(states[0].free);
    std::vector<HatchWeight> w = hatch_weights(states, surface);
    int level0 = 0, level1 = 0;
    for (size_t d = 0; d < surface.size(); ++d) (surface[d].hatch.position == 0 ? level0 : level1) += w[d].alpha > 0;
    EXPECT_EQ(level0, 3);
    EXPECT_EQ(level1, view == &s ? 0 : 5) << "sigma " << states[0].sigma;
  }
}

class HatchingStrokes : public testing::GlTest {};

// Both projections of the hatches agree, and the ID image, visibility and stroke raster
// agree fed the same inputs, at a frame in the middle of a transition.
TEST_F(HatchingStrokes, Parity) {
  Scene path = approaching_sphere();
  DecalSurface gpu = gpu::project_decals_through_gbuffer(path), ref = reference::project_decals_by_rays(path);
  ProjectionAgreement a = compare_projections(gpu, ref, std::vector<uint8_t>());
  std::printf("[hatch projection] %zu points: %.4f%% on the same face, max |bary diff| %.3g\n", a.points,
              100.0 * double(a.same_face) / double(a.points), a.max_bary_difference);
  EXPECT_GE(double(a.same_face), 0.99 * double(a.points));
  EXPECT_LE(a.max_bary_difference, 1e-3);
  int mid = -1;
  for (int i = 0; i < path.animation->frames && mid < 0; ++i) {
    HatchGroupState g = at_frame(path, ref, i).state;
    if (g.lod.from != g.lod.to && g.progress > 0.3 && g.progress < 0.7) mid = i;
  }
  ASSERT_GE(mid, 0) << "no frame in the middle of a transition";
  Scene scene = scene_at_frame(path, mid);
  const SurfaceStrokes strokes = surface_strokes(scene, ref);
  WindowLines lines = window_lines(scene, scene.params.get<StrokesParams>(), LineObjects::Strokes, nullptr, &strokes);
  size_t hatches = 0;
  for (const WindowPath& p : lines.paths) hatches += p.kind == LineKind::Hatching;
  ASSERT_GT(hatches, 7u);
  for (const StageParity& r : run_parity(scene, {"id_image", "visibility", "stroke"})) {
    std::printf("[hatching frame %d] %s  [%s]\n", mid, format_diff(r.name, r.diff).c_str(), r.note.c_str());
    EXPECT_TRUE(r.pass) << r.name << ": " << r.note;
  }
}

}  // namespace
}  // namespace plumbago
