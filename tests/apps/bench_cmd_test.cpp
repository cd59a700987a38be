// `plumbago bench`: the papers' claims table (--paper) and the accuracy options
// (--save/--against) the experiments/ studies are built on. Structure only: a benchmark
// reports times and never asserts them.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>

#include "bench/paper_claims.hpp"
#include "common/pencil/compose.hpp"
#include "tests/support/cli_run.hpp"

namespace plumbago {
namespace {

namespace fs = std::filesystem;
using testing::CliRun;

class BenchCmd : public ::testing::Test {
 protected:
  std::string path(const std::string& name) const { return tmp_.path(name); }
  CliRun run(const std::string& args) const { return testing::run_cli(args, tmp_); }
  testing::TempDir tmp_;
};

TEST_F(BenchCmd, PaperTableHasEveryClaimWithOursNextToIt) {
  CliRun r = run("bench --paper --json --size 48x48 --frames 1");
  ASSERT_EQ(r.code, 0) << r.err;
  auto j = nlohmann::json::parse(r.out);
  EXPECT_FALSE(j.at("machine").get<std::string>().empty());
  EXPECT_FALSE(j.at("renderer").get<std::string>().empty());
  const auto& claims = paper_claims();
  ASSERT_EQ(j.at("claims").size(), claims.size());
  bool any_ours = false;
  for (size_t i = 0; i < claims.size(); ++i) {
    const auto& c = j["claims"][i];
    EXPECT_EQ(c.at("paper"), claims[i].paper);
    EXPECT_EQ(c.at("fps_low").get<double>(), claims[i].fps_low);
    EXPECT_LE(claims[i].fps_low, claims[i].fps_high) << claims[i].paper;
    EXPECT_EQ(c.at("ours_scene"), claims[i].plumbago_scene);
    if (claims[i].plumbago_scene.empty()) {
      EXPECT_TRUE(c.at("ours_gpu").is_null());
      EXPECT_FALSE(c.at("note").get<std::string>().empty()) << "a claim with no configuration of ours says why";
      continue;
    }
    EXPECT_TRUE(fs::exists(fs::path(PLUMBAGO_SOURCE_DIR) / claims[i].plumbago_scene)) << claims[i].plumbago_scene;
    if (c.at("ours_gpu").is_null()) {  // e.g. the shared models are absent: it says so
      EXPECT_EQ(c.at("note").get<std::string>().rfind("not run: ", 0), 0u) << c.dump();
      continue;
    }
    any_ours = true;
    for (const char* backend : {"ours_gpu", "ours_reference"}) {
      const auto& ours = c.at(backend);
      EXPECT_GT(ours.at("fps").get<double>(), 0) << backend;
      EXPECT_GT(ours.at("faces").get<int>(), 0) << backend;
      EXPECT_EQ(ours.at("size"), nlohmann::json({48, 48}));
    }
  }
  if (!any_ours) GTEST_SKIP() << "no scene of the claims table could be loaded (shared models absent?)";
}

TEST_F(BenchCmd, PaperTextNamesTheMachineTheRendererAndEveryPaper) {
  CliRun r = run("bench --paper --size 48x48 --frames 1 --backend gpu");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("machine:"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("GL renderer:"), std::string::npos) << r.out;
  for (const auto& c : paper_claims()) {
    EXPECT_NE(r.out.find(c.paper), std::string::npos) << c.paper;
    EXPECT_NE(r.out.find(c.scene), std::string::npos) << c.scene;
  }
}

// --limits: every probe timed, and every GPU pass read against the probe its pass declares
// (a raster pass against the raster probe, the visibility test against compute work).
TEST_F(BenchCmd, LimitsTimeEveryProbeAndReadEachPassAgainstItsOwn) {
  const std::map<std::string, std::string> kProbeOf = {{"gbuffer", "raster"},
                                                       {"id_image", "raster"},
                                                       {"visibility", "compute"},
                                                       {"edge_detect+contour_light", "fetch3x3"}};
  std::string strokes = std::string(PLUMBAGO_SOURCE_DIR) + "/scenes/torus_strokes.json";
  CliRun r = run("bench builtin:pencil " + strokes + " --limits --json --size 64x48 --frames 2 --backend gpu");
  ASSERT_EQ(r.code, 0) << r.err;
  auto j = nlohmann::json::parse(r.out);
  ASSERT_EQ(j.at("results").size(), 2u);
  for (const auto& result : j["results"]) {
    const auto& limits = result.at("limits");
    for (const char* probe : {"fullscreen", "fetch3x3", "compute", "compute3x3", "raster", "readback"})
      EXPECT_GT(limits.at(probe).get<double>(), 0) << probe;
    const auto& multiples = result.at("probe_multiples");
    EXPECT_EQ(multiples.size(), result.at("stages").size());
    for (const auto& [pass, m] : multiples.items()) {
      EXPECT_GE(m.at("multiple").get<double>(), 0) << pass;
      auto it = kProbeOf.find(pass);
      if (it != kProbeOf.end()) {
        EXPECT_EQ(m.at("probe"), it->second) << pass;
      }
    }
  }
  EXPECT_TRUE(j["results"][1].at("probe_multiples").contains("visibility"));
}

// Per GPU frame: the CPU time of the GL thread, at most the frame's wall time, the bytes
// read back (none: the pencil frame reads nothing, nor the strokes frame once the warm-up
// frame has sized its buffers), and what the stroke stages made.
TEST_F(BenchCmd, GpuFramesReportHostTimeAndReadback) {
  std::ofstream(path("tables.json")) << R"({"objects": [{"mesh": {"procedural": "torus"}, "style": "strokes"}],
      "effects": ["line_tables"]})";
  CliRun r = run("bench builtin:pencil " + path("tables.json") + " --json --size 64x48 --frames 3 --backend gpu");
  ASSERT_EQ(r.code, 0) << r.err;
  auto j = nlohmann::json::parse(r.out);
  ASSERT_EQ(j.at("results").size(), 2u);
  for (const auto& result : j["results"]) {
    EXPECT_GT(result.at("host_ms").get<double>(), 0);
    EXPECT_LE(result.at("host_ms").get<double>(), result.at("frame_ms").get<double>());
  }
  EXPECT_EQ(j["results"][0].at("readback_bytes").get<double>(), 0) << "the pencil frame reads nothing back";
  EXPECT_EQ(j["results"][1].at("readback_bytes").get<double>(), 0) << "nor the strokes frame";
  const auto& counts = j["results"][1].at("counts");
  for (const char* name : {"segments", "chains", "paths", "samples", "strokes"})
    EXPECT_GT(counts.at(name).get<double>(), 0) << name;
  EXPECT_LE(counts.at("chains").get<double>(), counts.at("segments").get<double>());
}

// A camera path's frames report the same: one renderer moves along the path, and the first
// frame after each move sizes the stroke buffers again, reading back their counts.
TEST_F(BenchCmd, CameraPathFramesReportHostTimeAndReadback) {
  std::ofstream(path("orbit.json")) << R"({"objects": [{"mesh": {"procedural": "torus"}, "style": "strokes"}],
      "effects": ["line_tables"], "animation": {"orbit_deg": 30, "frames": 3}})";
  CliRun r = run("bench " + path("orbit.json") + " --json --size 64x48 --frames 3 --backend gpu");
  ASSERT_EQ(r.code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  const auto& result = j.at("results").at(0);
  ASSERT_EQ(result.at("path").at("timed_frames").get<int>(), 3);
  EXPECT_GT(result.at("host_ms").get<double>(), 0);
  EXPECT_LE(result.at("host_ms").get<double>(), result.at("frame_ms").get<double>());
  EXPECT_GT(result.at("readback_bytes").get<double>(), 0) << "a moved frame sizes its buffers";
}

TEST_F(BenchCmd, PaperRefusesAScene) {
  CliRun r = run("bench --paper builtin:torus");
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("--paper"), std::string::npos) << r.err;
}

TEST_F(BenchCmd, AgainstItsOwnSavedFrameIsZeroAndAgainstAnotherSettingIsNot) {
  std::string base = "bench builtin:torus --size 64x48 --frames 1 --backend gpu --json --buffers compose.color ";
  ASSERT_EQ(run(base + "--save " + path("saved")).code, 0);
  ASSERT_TRUE(fs::exists(path("saved/gpu/compose.color.exr")));
  CliRun same = run(base + "--against " + path("saved/gpu"));
  ASSERT_EQ(same.code, 0) << same.err;
  auto e = nlohmann::json::parse(same.out)["results"][0]["errors"][kComposeColor.name];
  EXPECT_EQ(e.at("max_abs").get<double>(), 0.0) << "the same scene rendered twice differs";
  CliRun other = run(base + "--set contour.copies=1 --against " + path("saved/gpu"));
  ASSERT_EQ(other.code, 0) << other.err;
  auto o = nlohmann::json::parse(other.out)["results"][0]["errors"][kComposeColor.name];
  EXPECT_GT(o.at("rmse").get<double>(), 0.0);
  EXPECT_LE(o.at("mean_abs").get<double>(), o.at("rmse").get<double>());
  EXPECT_LE(o.at("rmse").get<double>(), o.at("max_abs").get<double>());
}

TEST_F(BenchCmd, AgainstAnImageOfAnotherSizeIsRefused) {
  ASSERT_EQ(
      run("bench builtin:torus --size 64x48 --frames 1 --backend gpu --buffers compose.color --save " + path("s")).code,
      0);
  CliRun r = run("bench builtin:torus --size 32x32 --frames 1 --backend gpu --buffers compose.color --against " +
                 path("s/gpu"));
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("--against"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace plumbago
