// The stage descriptors (common/core/stage.hpp) and what follows from them: the pass table,
// each backend's implementations, the GPU's fused passes, the dumps.
#include <gtest/gtest.h>

#include <algorithm>
#include <set>

#include "common/core/passes.hpp"
#include "common/core/stage.hpp"
#include "gpu/core/pipeline.hpp"
#include "gpu/core/stage.hpp"
#include "reference/core/pipeline.hpp"
#include "tests/support/test_scenes.hpp"

namespace plumbago {
namespace {

size_t position(const std::string& stage) {
  const auto& t = stage_table();
  return size_t(std::find_if(t.begin(), t.end(), [&](const StageDesc& s) { return s.name == stage; }) - t.begin());
}

TEST(Stages, EveryInputIsAnOutputOfAnEarlierStage) {
  ASSERT_GE(stage_table().size(), 17u);
  for (const StageDesc& s : stage_table())
    for (const Input& in : s.inputs) {
      EXPECT_NO_THROW(find_output(in.buffer())) << s.name << " reads " << in.buffer();
      EXPECT_LT(position(stage_of(in.buffer()).name), position(s.name)) << s.name << " reads " << in.buffer();
    }
}

TEST(Stages, ParameterPrefixesAreUniqueAndEveryStageNamesKnownOnes) {
  std::set<std::string> prefixes;
  for (const ParamSpec& p : param_specs()) prefixes.insert(p.key.substr(0, p.key.find('.')));
  EXPECT_TRUE(prefixes.count("contour") && prefixes.count("contour_light")) << "the two contour structs keep apart";
  for (const StageDesc& s : stage_table())
    for (const std::string& p : s.params) EXPECT_TRUE(prefixes.count(p)) << s.name << " reads " << p << ".*";
}

TEST(Stages, UnknownNamesAreRefusedWithTheKnownOnes) {
  try {
    find_stage("contour_lihgt");
    FAIL() << "accepted an unknown stage";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("contour_light"), std::string::npos) << e.what();
  }
  EXPECT_THROW(find_output("edge_detect.darkness"), std::invalid_argument);
}

TEST(Stages, EveryFrameStageIsImplementedOnBothBackends) {
  EXPECT_NO_THROW(reference::check_implementations());
  EXPECT_NO_THROW(gpu::check_implementations());
  for (const StageDesc& s : stage_table()) {
    if (s.kind != StageKind::Frame) continue;
    EXPECT_NO_THROW(reference::implementation(s.name)) << s.name;
    const auto& passes = gpu::registered_passes();
    EXPECT_TRUE(std::any_of(passes.begin(), passes.end(), [&](const gpu::GpuPassDef& p) {
      return std::find(p.stages.begin(), p.stages.end(), s.name) != p.stages.end();
    })) << s.name;
  }
}

// A pass asking whether a misspelled stage ran gets an error, not a silent false.
TEST(Stages, AskingWhetherAnUnknownStageRanIsAnError) {
  Scene scene = testing::builtin_at("torus", 32, 24);
  Preprocessed pre;
  gpu::GpuFrame f(scene, pre, frame_stages(passes_for(scene.effects, scene.params)));
  EXPECT_TRUE(f.ran("contour_light"));
  EXPECT_FALSE(f.ran("pencil_interior"));
  EXPECT_THROW(f.ran("contour_lihgt"), std::invalid_argument);
}

std::vector<std::string> pass_names(const std::vector<std::string>& effects) {
  ParamSet params;
  StageConfig config{params, effects};
  std::vector<std::string> names;
  for (const gpu::GpuPassDef* p : gpu::plan_passes(frame_stages(passes_for(effects, params)), config))
    names.push_back(p->name());
  return names;
}

// A fused pass runs where its last stage would: the composition draws the contours
// whatever runs between multiple contours and it in the registry.
TEST(Stages, TheGpuFusesWhatItCanAndRunsAloneTheRest) {
  EXPECT_EQ(pass_names({"contours", "interior"}),
            (std::vector<std::string>{"gbuffer", "edge_detect+contour_light", "interior_intensity+pencil_interior",
                                      "multi_contour+compose"}));
  EXPECT_EQ(pass_names({"interior"}),
            (std::vector<std::string>{"gbuffer", "interior_intensity+pencil_interior", "compose"}));
  EXPECT_EQ(pass_names({"paper"}), (std::vector<std::string>{"compose"}));
}

// A dump holds exactly the declared outputs of the stages that ran, on both backends.
class StageDumps : public testing::GlTest {};

TEST_F(StageDumps, HoldTheDeclaredOutputsOnBothBackends) {
  Scene scene = testing::builtin_at("torus", 96, 72);
  for (auto effects :
       {std::vector<std::string>{"contours"}, std::vector<std::string>{"contours", "interior", "paper"}}) {
    scene.effects = effects;
    std::vector<std::string> declared =
        dumped_buffers(frame_stages(passes_for(effects, scene.params)), {scene.params, effects});
    std::sort(declared.begin(), declared.end());
    ASSERT_GE(declared.size(), 8u);
    for (const Frame& f : {reference::render(scene, {true}), gpu::Renderer(scene).render({true})}) {
      std::vector<std::string> names;
      for (const auto& [name, img] : f.buffers) names.push_back(name);
      EXPECT_EQ(names, declared);
    }
  }
}

}  // namespace
}  // namespace plumbago
