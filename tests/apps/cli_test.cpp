// The command line as a user meets it: exit codes, messages naming file/line/key, and no
// output file left behind by a failed run (docs/design.md, principle 7).
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>

#include "common/core/passes.hpp"
#include "common/util/image.hpp"
#include "tests/support/cli_run.hpp"

namespace plumbago {
namespace {

namespace fs = std::filesystem;
using testing::CliRun;

class Cli : public ::testing::Test {
 protected:
  std::string path(const std::string& name) const { return tmp_.path(name); }
  void write(const std::string& name, const std::string& text) const { tmp_.write(name, text); }
  CliRun run(const std::string& args) const { return testing::run_cli(args, tmp_); }

  // Exit code 2, the message contains each of `needles`, no output image, no partial file.
  void expect_refused(const std::string& args, std::initializer_list<std::string> needles) const {
    expect_refused_as_is(args + " -o " + path("out.png"), needles);
  }

  // The same for a command line given whole; `blockers` are what the test put in the way.
  void expect_refused_as_is(const std::string& args, std::initializer_list<std::string> needles,
                            const std::set<std::string>& blockers = {}) const {
    CliRun r = run(args);
    EXPECT_EQ(r.code, 2) << r.err;
    for (const auto& n : needles) EXPECT_NE(r.err.find(n), std::string::npos) << "'" << n << "' not in: " << r.err;
    for (const auto& e : fs::recursive_directory_iterator(tmp_.dir())) {
      std::string name = fs::relative(e.path(), tmp_.dir()).string();
      EXPECT_TRUE(name == "stdout" || name == "stderr" || e.path().extension() == ".json" ||
                  e.path().extension() == ".obj" || blockers.count(name))
          << "left behind: " << e.path();
    }
  }

  testing::TempDir tmp_;
};

TEST_F(Cli, TexturesWritesEveryGeneratedTextureIncludingEachSketchyStylesNoise) {
  CliRun r = run("textures --size 64x64 --set pencil_textures.layers=8 --set pencil_textures.size=64 --out " +
                 path("textures"));
  ASSERT_EQ(r.code, 0) << r.err;
  for (const char* name : {"pencil_layer_00", "pencil_layer_07", "paper_normal", "contour_offsets_0", "sketchy_noise",
                           "sketchy_white_noise", "sketchy_noise_3d_slice0"})
    EXPECT_TRUE(fs::exists(path("textures/" + std::string(name) + ".png"))) << name;
  EXPECT_FALSE(fs::exists(path("textures/pencil_layer_08.png")));
}

TEST_F(Cli, RendersTheBuiltinSceneAndReportsWhatRan) {
  CliRun r = run("render --size 160x120 --stats --json -o " + path("out.png"));
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_TRUE(fs::exists(path("out.png")));
  auto j = nlohmann::json::parse(r.out);
  ASSERT_TRUE(j["ran"].is_array());
  std::vector<std::string> ran;
  for (const auto& p : j["ran"]) {
    ran.push_back(p["name"]);
    EXPECT_GE(p["ms"].get<double>(), 0.0);
  }
  for (const char* stage :
       {"distortion", "contour_texture", "gbuffer", "edge_detect", "contour_light", "multi_contour", "compose"})
    EXPECT_NE(std::find(ran.begin(), ran.end(), stage), ran.end()) << stage;
  EXPECT_FALSE(j["renderer"].get<std::string>().empty());
}

TEST_F(Cli, MissingSceneFile) { expect_refused("render " + path("nope.json"), {"nope.json"}); }

TEST_F(Cli, MalformedSceneJsonNamesTheLine) {
  write("bad.json", "{\n  \"mesh\": {\"procedural\": \"torus\"},\n  \"seed\": ,\n}\n");
  expect_refused("render " + path("bad.json"), {"bad.json", "line 3"});
}

TEST_F(Cli, UnknownEffectNamesTheKey) {
  write("fx.json", R"({"mesh": {"procedural": "torus"}, "effects": ["contours", "watercolor"]})");
  expect_refused("render " + path("fx.json"), {"fx.json", "/effects/1", "watercolor"});
}

TEST_F(Cli, UnknownParameterOnTheCommandLine) {
  expect_refused("render --set edge.depth_scal=3", {"edge.depth_scal", "edge.depth_scale"});
}

TEST_F(Cli, OutOfRangeParameterInASceneFile) {
  write("p.json", R"({"mesh": {"procedural": "torus"}, "params": {"edge.depth_scale": -4}})");
  expect_refused("render " + path("p.json"), {"p.json", "/params/edge.depth_scale", "out of range"});
}

TEST_F(Cli, NanCoordinatesNameTheMeshFileAndLine) {
  write("nan.obj", "v 0 0 0\nv 1 0 0\nv nan 1 0\nf 1 2 3\n");
  write("nan.json", R"({"mesh": "nan.obj"})");
  expect_refused("render " + path("nan.json"), {"nan.obj", "3"});
}

TEST_F(Cli, BadSizeIsRefused) { expect_refused("render --size 0x10", {"--size"}); }

// A camera beyond the largest coordinate is refused before any backend sees it: it made
// Embree abort (SIGABRT) in render, compare and bench.
TEST_F(Cli, FarAwayCameraIsRefusedOnEveryCommand) {
  write("far.json", R"({"mesh": {"procedural": "torus"}, "camera": {"eye": [1e20, 0, 0]}})");
  for (const char* command : {"render --backend reference -o ", "compare --out ", "bench --frames 1 --save "})
    expect_refused_as_is(command + path("out") + " " + path("far.json"), {"far.json", "/camera/eye", "beyond"});
}

TEST_F(Cli, NumberBeyondDoubleRangeNamesTheLine) {
  write("big.json", "{\"mesh\": {\"procedural\": \"torus\"},\n \"camera\": {\"far\": 1e400}}");
  expect_refused("render " + path("big.json"), {"big.json", "line 2", "1e400"});
}

// --size changes the horizontal field of view: too narrow a window is refused.
TEST_F(Cli, SizeThatNarrowsTheViewTooFarIsRefused) {
  write("narrow.json", R"({"mesh": {"procedural": "torus"}, "camera": {"eye": [0, 0, 0.6], "target": [0, 1, 0.6],
                           "up": [0, 0, 1], "fov_deg": 0.01, "near": 0.1, "far": 5}})");
  ASSERT_EQ(run("render " + path("narrow.json") + " --size 16x16 -o " + path("ok.png")).code, 0);
  fs::remove(path("ok.png"));
  expect_refused("render " + path("narrow.json") + " --size 1x100", {"--size 1x100", "narrow.json", "/camera/fov_deg"});
}

// Every output location is checked before the first file is written: a dump folder that
// is a file, or one dump target blocked by a folder, leaves neither the image nor a dump.
TEST_F(Cli, BlockedDumpLeavesNoImage) {
  write("blocker", "");
  write("s.json", R"({"mesh": {"procedural": "torus"}, "resolution": [32, 24]})");
  for (const char* backend : {"gpu", "reference"})
    for (const char* dump : {"blocker", "blocker/stages"})
      expect_refused_as_is("render " + path("s.json") + " --backend " + backend + " -o " + path("out.png") +
                               " --dump-stages " + path(dump),
                           {"blocker", "is a file, not a folder"}, {"blocker"});
  fs::create_directories(path("stages/gpu.gbuffer.normal.png"));
  expect_refused_as_is("render " + path("s.json") + " -o " + path("out.png") + " --dump-stages " + path("stages"),
                       {"gpu.gbuffer.normal.png", "is a folder"},
                       {"blocker", "stages", "stages/gpu.gbuffer.normal.png"});
}

TEST_F(Cli, TexturesWithOneTargetBlockedWritesNone) {
  fs::create_directories(path("textures/pencil_layer_03.png"));
  expect_refused_as_is(
      "textures --size 32x32 --set pencil_textures.layers=8 --set pencil_textures.size=32 --out " + path("textures"),
      {"pencil_layer_03.png"}, {"textures", "textures/pencil_layer_03.png"});
  write("file", "");
  expect_refused_as_is("textures --out " + path("file"), {"file", "not a folder"},
                       {"file", "textures", "textures/pencil_layer_03.png"});
}

TEST_F(Cli, BenchAgainstAMissingFolderIsRefused) {
  expect_refused_as_is("bench builtin:torus --frames 1 --size 32x32 --against " + path("nowhere"),
                       {"--against", "nowhere"});
}

// An empty effect list draws the blank page at the scene's size on both backends.
TEST_F(Cli, NoEffectDrawsABlankPageOfTheScenesSize) {
  write("blank.json", R"({"mesh": {"procedural": "torus"}, "resolution": [40, 30], "effects": []})");
  for (const char* backend : {"gpu", "reference"}) {
    CliRun r = run(std::string("render ") + path("blank.json") + " --backend " + backend + " -o " + path("blank.png"));
    ASSERT_EQ(r.code, 0) << r.err;
    Image img = read_image(path("blank.png"));
    EXPECT_EQ(img.width, 40);
    EXPECT_EQ(img.height, 30);
    for (float v : img.data) ASSERT_EQ(v, 1.0f) << backend;
  }
}

// Every effect the stages declare, with the stages it runs.
TEST_F(Cli, EffectsListsEveryEffectAndItsStages) {
  CliRun r = run("effects");
  ASSERT_EQ(r.code, 0) << r.err;
  ASSERT_GE(effect_table().size(), 5u);
  for (const EffectDef& e : effect_table()) EXPECT_NE(r.out.find(e.name + " "), std::string::npos) << e.name;
  EXPECT_NE(r.out.find("runs: distortion contour_texture gbuffer edge_detect contour_light multi_contour compose"),
            std::string::npos)
      << r.out;
}

TEST_F(Cli, CompareReportsEveryStageAsJson) {
  CliRun r = run("compare builtin:torus --size 160x120 --json");
  ASSERT_EQ(r.code, 0) << r.err << r.out;
  auto j = nlohmann::json::parse(r.out);
  EXPECT_TRUE(j["pass"].get<bool>());
  ASSERT_GE(j["stages"].size(), 3u);
  for (const auto& s : j["stages"])
    for (const char* key : {"name", "pass", "max_abs", "rmse", "over_tolerance", "tolerance"})
      EXPECT_TRUE(s.contains(key)) << key;
}

// compare holds both backends' frames and results at once: the budget that admits a render
// of the scene refuses its comparison, before either backend starts, with what it would need.
TEST_F(Cli, CompareOverTheMemoryBudgetIsRefusedWhereRenderFits) {
  const std::string budget = "--memory-budget-gb 0.6 ", scene = " builtin:torus --size 800x800";
  CliRun r = run(budget + "render" + scene + " -o " + path("out.png"));
  EXPECT_EQ(r.code, 0) << r.err;
  fs::remove(path("out.png"));
  expect_refused_as_is(budget + "compare" + scene, {"compare at 800x800", "over the memory budget of 0.6 GB"});
}

// Every compared output can be written as images, the corner angles and the fused
// passes' outputs too (this failed on the angles' six channels, after half the files).
TEST_F(Cli, CompareWritesEveryOutputAsImages) {
  write("pencil.json", R"({"mesh": {"procedural": "torus"}, "resolution": [96, 72],
                           "effects": ["contours", "interior", "crosshatch", "paper"]})");
  CliRun r = run("compare " + path("pencil.json") + " --json --out " + path("parity"));
  ASSERT_EQ(r.code, 0) << r.err << r.out;
  auto j = nlohmann::json::parse(r.out);
  ASSERT_GE(j["stages"].size(), 15u);
  for (const auto& s : j["stages"])
    for (const char* kind : {".reference.png", ".gpu.png", ".diff.png"}) {
      std::string file = path("parity") + "/" + s["name"].get<std::string>() + kind;
      EXPECT_TRUE(fs::exists(file)) << file;
    }
  EXPECT_TRUE(fs::exists(path("parity") + "/gbuffer.theta_min.diff.png"));
}

TEST_F(Cli, DumpStagesWritesEveryIntermediateBufferOnBothBackends) {
  write("all.json", R"({"mesh": {"procedural": "torus"}, "resolution": [96, 72],
                        "effects": ["contours", "interior", "crosshatch", "paper"]})");
  for (const char* backend : {"gpu", "reference"}) {
    CliRun r = run(std::string("render ") + path("all.json") + " --backend " + backend + " -o " + path("out.png") +
                   " --dump-stages " + path("stages"));
    ASSERT_EQ(r.code, 0) << r.err;
    for (const char* buffer : {"gbuffer.normal", "gbuffer.theta_min", "edge_detect.contour_darkness",
                               "contour_light.lit_contour_darkness", "multi_contour.contour_darkness",
                               "interior_intensity.intensity", "pencil_interior.interior_darkness", "compose.color"}) {
      std::string base = path("stages") + "/" + backend + "." + buffer;
      EXPECT_TRUE(fs::exists(base + ".png")) << base;
      EXPECT_TRUE(fs::exists(base + ".exr")) << base;
    }
  }
}

TEST_F(Cli, ParamsListsEveryStage) {
  CliRun r = run("params");
  ASSERT_EQ(r.code, 0) << r.err;
  for (const char* key : {"edge.depth_scale", "edge.normals", "compose.contrast"})
    EXPECT_NE(r.out.find(key), std::string::npos) << key;
  EXPECT_EQ(run("params nosuchstage").code, 2);
}

}  // namespace
}  // namespace plumbago
