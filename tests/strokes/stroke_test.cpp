// The styles of stroke runs (common/strokes/stroke.hpp RunStyles): what is random in a run's
// style belongs to the run, keyed by its path and its place along it, so that paths coming
// and going elsewhere leave it as it was (the GPU draws each run's numbers on their own).
#include <gtest/gtest.h>

#include <cmath>
#include <set>

#include "common/strokes/stroke.hpp"

namespace plumbago {
namespace {

// A straight crease from (x, 10) to (x + 200, 10) with key `key`.
WindowPath crease(uint32_t key, double x) {
  WindowPath p{LineKind::Crease, 0, false, true, key, {}, {}, {}, {}, {}, {}, 0, {}, 0};
  for (int k = 0; k <= 20; ++k) {
    p.window.push_back({x + 10.0 * k, 10.0});
    p.arc_px.push_back(10.0 * k);
    p.depth.push_back(1.0);
    p.world.push_back({0, 0, 0});
  }
  p.front_faces.assign(20, glm::uvec2(0));
  p.length_px = 200;
  return p;
}

// Every path with two visible runs, path after path.
Visibility two_runs_each(const WindowLines& lines) {
  Visibility v;
  for (uint32_t i = 0; i < lines.paths.size(); ++i) {
    v.runs.push_back(run_along(lines.paths[i], i, 10, 90, false, true, true));
    v.runs.push_back(run_along(lines.paths[i], i, 120, 190, false, true, true));
  }
  return v;
}

std::vector<double> displacements(const StrokeStyle& s) {
  std::vector<double> d;
  for (const StrokeOffset& o : s.offsets->offsets) d.push_back(o.displacement_px);
  return d;
}

// The offsets of path key 7's two runs, with `before` other paths listed ahead of it.
std::vector<std::vector<double>> offsets_of_key_7(const StrokeStyles& styles, int before) {
  WindowLines lines;
  for (int k = 0; k < before; ++k) lines.paths.push_back(crease(100 + k, 0));
  lines.paths.push_back(crease(7, 300));
  Visibility v = two_runs_each(lines);
  std::vector<RunStroke> strokes = run_strokes(lines, v, styles, 5);
  return {displacements(strokes[2 * before].style), displacements(strokes[2 * before + 1].style)};
}

StrokeStyles markov_creases() {
  StrokeStyles styles;
  styles.crease = load_stroke_style("sketchy_pencil");
  EXPECT_EQ(styles.crease.synthesis, OffsetSynthesis::Markov);
  return styles;
}

TEST(RunStyles, ARunKeepsItsSynthesizedOffsetsWhenOtherPathsComeBeforeIt) {
  StrokeStyles styles = markov_creases();
  auto alone = offsets_of_key_7(styles, 0);
  EXPECT_NE(alone[0], alone[1]);  // two runs of one path: two draws
  for (int before : {1, 3}) EXPECT_EQ(offsets_of_key_7(styles, before), alone) << before << " paths before it";
}

TEST(RunStyles, StampedExamplesGoInTurnAlongAPathFromOneItsKeyPicks) {
  StrokeStyles styles;
  for (int k = 0; k < 5; ++k)  // five examples told apart by their displacement
    styles.crease_examples.push_back({50.0, {{0.0, double(k), 1.0, false}, {1.0, double(k), 1.0, false}}});
  auto alone = offsets_of_key_7(styles, 0);
  EXPECT_EQ(std::fmod(alone[0][0] + 1, 5.0), alone[1][0]);  // the next example, wrapping
  EXPECT_EQ(offsets_of_key_7(styles, 2), alone);
  std::set<double> starts;  // the first example differs from key to key
  for (uint32_t key = 0; key < 40; ++key) {
    WindowLines lines;
    lines.paths.push_back(crease(key, 0));
    starts.insert(displacements(run_strokes(lines, two_runs_each(lines), styles, 5)[0].style)[0]);
  }
  EXPECT_EQ(starts.size(), 5u);
}

}  // namespace
}  // namespace plumbago
