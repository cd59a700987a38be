// plumbago lines (the stroke issue's command line contract): every path as JSON with
// world and window points and per-point visibility, the visible strokes as SVG, and bad
// input refused with nothing written.
#include <gtest/gtest.h>

#include <filesystem>
#include <map>
#include <set>

#include <nlohmann/json.hpp>

#include "tests/support/cli_run.hpp"

namespace plumbago {
namespace {

namespace fs = std::filesystem;

const char* kCube = R"({"objects": [{"mesh": {"procedural": "cube"}, "style": "strokes"}], "resolution": [200, 160],
  "camera": {"eye": [2.2, 1.7, 2.6], "target": [0, 0, 0], "up": [0, 1, 0]}})";

class LinesCommand : public ::testing::Test {
 protected:
  testing::CliRun run(const std::string& args) const { return testing::run_cli(args, tmp_); }
  testing::TempDir tmp_;
};

TEST_F(LinesCommand, JsonHasEveryPathWithItsVisibility) {
  tmp_.write("cube.json", kCube);
  for (const char* backend : {"gpu", "reference"}) {
    testing::CliRun r =
        run("lines " + tmp_.path("cube.json") + " --backend " + backend + " -o " + tmp_.path("lines.json"));
    ASSERT_EQ(r.code, 0) << r.err;
    auto j = nlohmann::json::parse(testing::slurp(tmp_.path("lines.json")));
    ASSERT_EQ(j["paths"].size(), 12u);  // the cube's crease edges
    int hidden_paths = 0;
    for (const auto& p : j["paths"]) {
      EXPECT_EQ(p["kind"], "crease");
      EXPECT_EQ(p["points"].size(), p["screen"].size());
      EXPECT_EQ(p["points"].size(), p["visible"].size());
      bool any = false;
      for (const auto& v : p["visible"]) any = any || v.get<bool>();
      hidden_paths += !any;
    }
    EXPECT_EQ(hidden_paths, 3) << backend;  // the edges at the far corner
  }
}

TEST_F(LinesCommand, SvgHasOnePathPerVisibleRun) {
  tmp_.write("cube.json", kCube);
  testing::CliRun r = run("lines " + tmp_.path("cube.json") + " -o " + tmp_.path("lines.svg"));
  ASSERT_EQ(r.code, 0) << r.err;
  std::string svg = testing::slurp(tmp_.path("lines.svg"));
  size_t paths = 0;
  for (size_t at = svg.find("<path"); at != std::string::npos; at = svg.find("<path", at + 1)) ++paths;
  EXPECT_EQ(paths, 9u);  // the nine visible edges, each one run
  EXPECT_NE(svg.find("fill-opacity"), std::string::npos);
}

TEST_F(LinesCommand, DecalsAreLinesToo) {
  tmp_.write("cube.strokes.json", R"({"camera": {"eye": [2.2, 1.7, 2.6], "target": [0, 0, 0], "up": [0, 1, 0],
    "fov_deg": 35, "near": 1, "far": 10}, "resolution": [200, 160],
    "strokes": [{"role": "decal", "points": [[100, 60, 1], [104, 50, 1]]}]})");
  std::string scene(kCube);
  tmp_.write("cube.json", scene.insert(scene.rfind('}'), R"(, "stroke_files": ["cube.strokes.json"])"));
  for (const char* backend : {"gpu", "reference"}) {
    testing::CliRun r = run("lines " + tmp_.path("cube.json") + " --backend " + backend + " -o " + tmp_.path("l.json"));
    ASSERT_EQ(r.code, 0) << r.err;
    auto j = nlohmann::json::parse(testing::slurp(tmp_.path("l.json")));
    ASSERT_EQ(j["paths"].size(), 13u) << backend;  // 12 creases and the decal, last
    EXPECT_EQ(j["paths"][12]["kind"], "decal");
    EXPECT_NE(r.out.find("13 paths, 10 shown, 10 visible runs"), std::string::npos) << r.out;
  }
  ASSERT_EQ(run("lines " + tmp_.path("cube.json") + " -o " + tmp_.path("l.svg")).code, 0);
  EXPECT_NE(testing::slurp(tmp_.path("l.svg")).find("class=\"decal\""), std::string::npos);
}

// Each hatch says its group and the group's kind (Kalnins et al. 2002, §6): three strokes of a
// structured group and one of a free group, drawn on the cube's front face.
TEST_F(LinesCommand, HatchesNameTheirGroupAndItsKind) {
  tmp_.write("cube.strokes.json", R"({"camera": {"eye": [2.2, 1.7, 2.6], "target": [0, 0, 0], "up": [0, 1, 0],
    "fov_deg": 35, "near": 1, "far": 10}, "resolution": [200, 160],
    "strokes": [{"role": "hatching", "group": 0, "points": [[95, 45, 1], [105, 55, 1]]},
                {"role": "hatching", "group": 0, "points": [[95, 50, 1], [105, 60, 1]]},
                {"role": "hatching", "group": 0, "points": [[95, 55, 1], [105, 65, 1]]},
                {"role": "hatching", "group": 1, "free": true, "points": [[98, 40, 1], [110, 44, 1]]}]})");
  std::string scene(kCube);
  tmp_.write("cube.json", scene.insert(scene.rfind('}'), R"(, "stroke_files": ["cube.strokes.json"])"));
  for (const char* backend : {"gpu", "reference"}) {
    testing::CliRun r = run("lines " + tmp_.path("cube.json") + " --backend " + backend + " -o " + tmp_.path("l.json"));
    ASSERT_EQ(r.code, 0) << r.err;
    std::map<std::string, std::set<int>> groups;  // kind -> groups
    const auto j = nlohmann::json::parse(testing::slurp(tmp_.path("l.json")));
    for (const auto& path : j["paths"]) {
      EXPECT_EQ(path.contains("hatching"), path["kind"] == "hatching") << path["kind"];
      if (path["kind"] == "hatching") groups[path["hatching"]].insert(path["group"].get<int>());
    }
    EXPECT_EQ(groups["structured"], std::set<int>{0}) << backend;
    EXPECT_EQ(groups["free"], std::set<int>{1}) << backend;
  }
}

TEST_F(LinesCommand, RefusesAnUnknownStyleAndWritesNothing) {
  tmp_.write("bad.json",
             R"({"objects": [{"mesh": {"procedural": "cube"}, "style": "strokes"}], "strokes": {"crease": "nope"}})");
  testing::CliRun r = run("lines " + tmp_.path("bad.json") + " -o " + tmp_.path("lines.json"));
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("/strokes/crease"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(tmp_.path("lines.json")));
}

TEST_F(LinesCommand, RenderStatsListStrokePassesOnlyWithStrokeObjects) {
  tmp_.write("cube.json", kCube);
  testing::CliRun with = run("render " + tmp_.path("cube.json") + " --stats --json -o " + tmp_.path("a.png"));
  testing::CliRun without = run("render --size 80x60 --stats --json -o " + tmp_.path("b.png"));
  ASSERT_EQ(with.code, 0) << with.err;
  ASSERT_EQ(without.code, 0) << without.err;
  for (const char* pass : {"id_image", "visibility", "stroke"}) {
    EXPECT_NE(with.out.find(std::string("\"") + pass + "\""), std::string::npos) << pass;
    EXPECT_EQ(without.out.find(std::string("\"") + pass + "\""), std::string::npos) << pass;
  }
}

}  // namespace
}  // namespace plumbago
