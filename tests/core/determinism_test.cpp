// Identical runs give identical files: a scene, and every scene in scenes/, rendered twice
// on each backend with every stage dumped, gives the same bytes in every PNG and EXR
// (issue 21: the EXR header used to carry the time of writing). SOURCE_DATE_EPOCH, when
// set, is the date written.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <map>
#include <regex>

#include "tests/support/cli_run.hpp"

namespace plumbago {
namespace {

namespace fs = std::filesystem;

class Determinism : public ::testing::Test {
 protected:
  Determinism() {
    scene_ = tmp_.write("scene.json", R"({
      "objects": [{"mesh": {"procedural": "torus"}},
                  {"mesh": {"procedural": "sphere"}, "style": "sketchy",
                   "transform": [0.5, 0, 0, 0, 0, 0.5, 0, 0, 0, 0, 0.5, 0, 1.2, 0, 0, 1]}],
      "resolution": [64, 48],
      "effects": ["contours", "interior", "crosshatch", "paper", "sketchy"]})");
  }

  // Every file a render writes (the image and its dumps), by name, with its bytes.
  std::map<std::string, std::string> render(const std::string& backend, const std::string& run,
                                            const std::string& wrapper = "", const std::string& extra = "") const {
    const std::string dir = tmp_.path(backend + run);
    fs::create_directories(dir);
    testing::CliRun r = testing::run_cli("render " + scene_ + " --backend " + backend + " -o " + dir + "/image.exr" +
                                             " --dump-stages " + dir + "/dump " + extra,
                                         tmp_, wrapper);
    EXPECT_EQ(r.code, 0) << r.err;
    std::map<std::string, std::string> files;
    for (const auto& e : fs::recursive_directory_iterator(dir))
      if (e.is_regular_file()) files[fs::relative(e.path(), dir).string()] = testing::slurp(e.path().string());
    return files;
  }

  // Two runs on each backend write the same files, byte for byte, and none carries a date:
  // two runs a second apart could still agree on one to the second ("YYYY:MM:DD
  // hh:mm:ss", as OpenImageIO writes it).
  void expect_identical_runs(const std::string& extra = "") const {
    const std::regex date(R"(\d{4}:\d\d:\d\d \d\d:\d\d:\d\d)");
    for (const char* backend : {"gpu", "reference"}) {
      auto first = render(backend, "1", kUndated, extra), second = render(backend, "2", kUndated, extra);
      EXPECT_GT(first.size(), 5u) << backend << ": too few dumps";
      ASSERT_EQ(first.size(), second.size()) << backend;
      for (const auto& [name, bytes] : first) {
        EXPECT_TRUE(second[name] == bytes) << backend << ": " << name << " differs";
        EXPECT_FALSE(std::regex_search(bytes, date)) << backend << ": " << name << " carries a date";
      }
    }
  }

  static constexpr const char* kUndated = "env -u SOURCE_DATE_EPOCH ";
  testing::TempDir tmp_;
  std::string scene_;
};

TEST_F(Determinism, TwoRunsWriteTheSameBytesOnEachBackend) { expect_identical_runs(); }

// Every scene in scenes/ (one of a shared model only where the model is there), small.
class SceneDeterminism : public Determinism, public ::testing::WithParamInterface<std::string> {};

TEST_P(SceneDeterminism, TwoRunsWriteTheSameBytesOnEachBackend) {
  scene_ = std::string(PLUMBAGO_SOURCE_DIR) + "/scenes/" + GetParam() + ".json";
  const std::regex mesh_file(R"re("([^"]*\.(obj|ply|off|stl))")re");
  std::string text = testing::slurp(scene_);
  for (std::smatch m; std::regex_search(text, m, mesh_file); text = m.suffix())
    if (!fs::exists(fs::path(scene_).parent_path() / m[1].str())) GTEST_SKIP() << "no " << m[1] << " here";
  expect_identical_runs("--size 48x36");
}

std::vector<std::string> example_scenes() {
  std::vector<std::string> names;
  for (const auto& e : fs::directory_iterator(std::string(PLUMBAGO_SOURCE_DIR) + "/scenes"))
    if (e.path().extension() == ".json" && !e.path().string().ends_with(".schema.json"))
      names.push_back(e.path().stem().string());
  std::sort(names.begin(), names.end());
  return names;
}

INSTANTIATE_TEST_SUITE_P(Scenes, SceneDeterminism, ::testing::ValuesIn(example_scenes()),
                         [](const ::testing::TestParamInfo<std::string>& info) { return info.param; });

TEST_F(Determinism, SourceDateEpochIsTheDateWritten) {
  auto files = render("reference", "dated", "env SOURCE_DATE_EPOCH=86400 ");
  EXPECT_NE(files["image.exr"].find("1970:01:02 00:00:00"), std::string::npos);
}

}  // namespace
}  // namespace plumbago
