// The memory budget over stroke processing (docs/bad-input.md, "Memory budget"): lines grow
// with faces and with the window, so their visibility samples and their strokes are held
// to the budget before any is made, and the refusal says what they would need.
#include <gtest/gtest.h>

#include <functional>
#include <stdexcept>
#include <string>

#include "common/core/params.hpp"
#include "common/strokes/stroke.hpp"
#include "common/strokes/visibility.hpp"
#include "common/util/memory_budget.hpp"

namespace plumbago {
namespace {

class StrokeMemory : public ::testing::Test {
 protected:
  void TearDown() override { set_memory_budget_gb(kDefaultMemoryBudgetGb); }
};

// `paths` silhouettes zigzagging across a 1000x1000 window, `turns` segments of about
// 980 px each.
WindowLines zigzags(int paths, int turns) {
  WindowLines lines;
  lines.width = lines.height = 1000;
  for (int i = 0; i < paths; ++i) {
    WindowPath p{LineKind::Silhouette, 0, false, true, uint32_t(i + 1), {}, {}, {}, {}, {}, {}};
    for (int k = 0; k <= turns; ++k) {
      glm::dvec2 at(k % 2 ? 990.0 : 10.0, 10.0 + (980.0 * k) / turns);
      if (k > 0) p.length_px += glm::distance(p.window.back(), at);
      p.window.push_back(at);
      p.arc_px.push_back(p.length_px);
    }
    lines.paths.push_back(p);
  }
  return lines;
}

std::string refusal(const std::function<void()>& run) {
  try {
    run();
  } catch (const std::length_error& e) {
    return e.what();
  }
  return "";
}

const SampleTest kAllVisible = [](const std::vector<VisibilitySample>& s) { return std::vector<uint8_t>(s.size(), 1); };

TEST_F(StrokeMemory, SamplesOfLinesOverTheBudgetAreRefusedBeforeAnyIsMade) {
  WindowLines lines = zigzags(20, 100);  // 1.96M px of lines: a million samples every 2 px
  StrokesParams p = ParamSet().get<StrokesParams>();
  set_memory_budget_gb(0.05);
  std::string why = refusal([&] { visible_runs(lines, p, kAllVisible); });
  EXPECT_NE(why.find("the visibility samples of 20 lines"), std::string::npos) << why;
  EXPECT_NE(why.find("memory budget of 0.05 GB"), std::string::npos) << why;
  set_memory_budget_gb(1);
  Visibility v = visible_runs(lines, p, kAllVisible);
  EXPECT_EQ(v.runs.size(), 20u);
  EXPECT_GT(v.flags.size(), 900'000u);  // what the refused budget would have had to hold
}

TEST_F(StrokeMemory, StrokesOfRunsOverTheBudgetAreRefusedBeforeAnyIsMade) {
  WindowLines lines = zigzags(20, 100);
  set_memory_budget_gb(1);
  Visibility v = visible_runs(lines, ParamSet().get<StrokesParams>(), kAllVisible);
  set_memory_budget_gb(0.2);  // the runs' ribbons take about 0.23 GB
  std::string why = refusal([&] { stroke_triangles(lines, v, StrokeStyles{}, 1); });
  EXPECT_NE(why.find("the strokes of 20 visible runs"), std::string::npos) << why;
  EXPECT_NE(why.find("resampled every 3.5 px"), std::string::npos) << why;
}

TEST_F(StrokeMemory, OrdinaryLinesAreNotRefused) {
  WindowLines lines = zigzags(4, 4);
  Visibility v = visible_runs(lines, ParamSet().get<StrokesParams>(), kAllVisible);
  EXPECT_FALSE(stroke_triangles(lines, v, StrokeStyles{}, 1).empty());
}

}  // namespace
}  // namespace plumbago
