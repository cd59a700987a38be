// Camera paths (common/scene/animation.hpp): the cameras along an orbit and a dolly, the
// refusals, `render -o DIR` writing the numbered frames, and `bench` timing the path.
#include <gtest/gtest.h>

#include <filesystem>
#include <glm/gtc/constants.hpp>

#include "common/scene/animation.hpp"
#include "common/scene/scene.hpp"
#include "common/util/image.hpp"
#include "tests/support/cli_run.hpp"

namespace plumbago {
namespace {

Scene animated(const std::string& animation) {
  return parse_scene(R"({"mesh": {"procedural": "torus"}, "resolution": [96, 72],
      "camera": {"eye": [0, 0, 6], "target": [0, 0, 0], "up": [0, 1, 0]}, "animation": )" +
                         animation + "}",
                     "animated.json", ".");
}

std::string refusal(const std::string& animation) {
  try {
    animated(animation);
  } catch (const SceneError& e) {
    return e.what();
  }
  return "accepted";
}

TEST(Animation, AnOrbitTurnsTheEyeAboutUpThroughTheTarget) {
  Scene s = animated(R"({"orbit_deg": 90, "frames": 3, "fps": 24})");
  ASSERT_TRUE(s.animation);
  EXPECT_DOUBLE_EQ(s.animation->time_s(2), 2.0 / 24);
  Scene first = scene_at_frame(s, 0), middle = scene_at_frame(s, 1), last = scene_at_frame(s, 2);
  EXPECT_EQ(first.camera.eye, s.camera.eye);
  glm::vec3 to_eye = s.camera.eye - s.camera.target;
  glm::vec3 turned = last.camera.eye - last.camera.target;  // +90 degrees about +y: (0, 0, 6) -> (6, 0, 0)
  EXPECT_NEAR(turned.x, to_eye.z, 1e-5);
  EXPECT_NEAR(turned.z, -to_eye.x, 1e-5);
  EXPECT_NEAR(glm::length(middle.camera.eye - middle.camera.target), glm::length(to_eye), 1e-5);
  EXPECT_NEAR(glm::dot(glm::normalize(middle.camera.eye - middle.camera.target), glm::normalize(to_eye)),
              std::cos(glm::quarter_pi<float>()), 1e-5);
  EXPECT_EQ(last.camera.near, s.camera.near);
  EXPECT_NE(last.lights[0].direction, s.lights[0].direction);  // the default light follows the camera
}

TEST(Animation, ADollyMovesTheEyeAlongTheViewAndRefitsThePlanes) {
  Scene s = animated(R"({"dolly": 3, "frames": 4})");
  Scene last = scene_at_frame(s, 3);
  EXPECT_NEAR(glm::distance(last.camera.eye, s.camera.eye), 3.0, 1e-5);
  EXPECT_NEAR(glm::distance(last.camera.eye, last.camera.target), glm::distance(s.camera.eye, s.camera.target) - 3,
              1e-5);
  EXPECT_LT(last.camera.far, s.camera.far);
  EXPECT_GT(last.camera.near, 0.0f);
}

TEST(Animation, PathsThatCannotBeRenderedAreRefusedWithTheirKey) {
  EXPECT_NE(refusal(R"({"orbit_deg": 90, "dolly": 1, "frames": 3})").find("/animation: give either"),
            std::string::npos);
  EXPECT_NE(refusal(R"({"orbit_deg": 90})").find("/animation/frames"), std::string::npos);
  EXPECT_NE(refusal(R"({"orbit_deg": 90, "frames": 0})").find("/animation/frames"), std::string::npos);
  EXPECT_NE(refusal(R"({"orbit_deg": 90, "frames": 2.5})").find("/animation/frames"), std::string::npos);
  EXPECT_NE(refusal(R"({"orbit_deg": 90, "frames": 3, "fps": 0})").find("/animation/fps"), std::string::npos);
  EXPECT_NE(refusal(R"({"orbit_deg": 1e5, "frames": 3})").find("/animation/orbit_deg"), std::string::npos);
  EXPECT_NE(refusal(R"({"orbit": 90, "frames": 3})").find("/animation/orbit: unknown key"), std::string::npos);
  // Through the target: frame 2 of 3 stands on it.
  std::string through = refusal(R"({"dolly": 6, "frames": 3})");
  EXPECT_NE(through.find("/animation/dolly: frame 2's camera"), std::string::npos) << through;
  // Past the target: frame 1 stands 4 beyond it and would look back at the scene.
  std::string past = refusal(R"({"dolly": 20, "frames": 3})");
  EXPECT_NE(past.find("/animation/dolly: frame 1's camera: the eye reaches or passes the target"), std::string::npos)
      << past;
  EXPECT_EQ(refusal(R"({"dolly": 5.9, "frames": 3})"), "accepted");
  // An orbit past 90 degrees looks at the target from behind where it started: not a dolly's fault.
  EXPECT_EQ(refusal(R"({"orbit_deg": 180, "frames": 3})"), "accepted");
  EXPECT_EQ(refusal(R"({"orbit_deg": -360, "frames": 37})"), "accepted");
}

class AnimationCli : public ::testing::Test {
 protected:
  testing::TempDir tmp;
  std::string scene = tmp.write("orbit.json", R"({"mesh": {"procedural": "torus"}, "resolution": [96, 72],
      "effects": ["contours", "interior"], "animation": {"orbit_deg": 60, "frames": 3}})");
};

TEST_F(AnimationCli, RenderToAFolderWritesEveryFrameAndFrameSelectsOne) {
  auto r = testing::run_cli("render " + scene + " -o " + tmp.path("frames"), tmp);
  ASSERT_EQ(r.code, 0) << r.err;
  std::vector<Image> frames;
  for (const char* name : {"frame_0000.png", "frame_0001.png", "frame_0002.png"})
    frames.push_back(read_image(tmp.path("frames/" + std::string(name))));
  EXPECT_FALSE(std::filesystem::exists(tmp.path("frames/frame_0003.png")));
  EXPECT_NE(frames[0].data, frames[1].data);
  EXPECT_NE(frames[1].data, frames[2].data);
  r = testing::run_cli("render " + scene + " --frame 2 -o " + tmp.path("two.png"), tmp);
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(read_image(tmp.path("two.png")).data, frames[2].data);
  r = testing::run_cli("render " + scene + " --frame 3 -o " + tmp.path("three.png"), tmp);
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("--frame 3"), std::string::npos) << r.err;
  EXPECT_FALSE(std::filesystem::exists(tmp.path("three.png")));
}

TEST_F(AnimationCli, ABlockedFolderLeavesNoFrame) {
  tmp.write("blocked", "a file where the folder should go");
  auto r = testing::run_cli("render " + scene + " -o " + tmp.path("blocked/frames"), tmp);
  EXPECT_EQ(r.code, 2);
  EXPECT_FALSE(std::filesystem::exists(tmp.path("blocked/frames")));
}

TEST_F(AnimationCli, BenchTimesThePathUpToItsFrames) {
  auto r = testing::run_cli("bench " + scene + " --json", tmp);
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("\"path\""), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("\"frames\": 3"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("\"timed_frames\": 3"), std::string::npos) << r.out;
  r = testing::run_cli("bench " + scene + " --json --backend gpu --frames 2", tmp);
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("\"timed_frames\": 2"), std::string::npos) << r.out;
}

// A long path stopped by a signal as soon as its first frame is being written: the command
// ends with 128 + the signal's number, and neither a frame nor the folder it made is left.
TEST_F(AnimationCli, AStoppedPathLeavesNothingBehind) {
  std::string long_path = tmp.write("long.json", R"({"mesh": {"procedural": "torus"}, "resolution": [96, 72],
      "effects": ["contours"], "animation": {"orbit_deg": 60, "frames": 20000}})");
  for (auto [signal, code] : {std::pair{"INT", 130}, {"TERM", 143}}) {
    std::string frames = tmp.path(std::string("frames_") + signal);
    std::string script = std::string(PLUMBAGO_CLI) + " render " + long_path + " -o " + frames + " 2>" +
                         tmp.path("stderr") + " & pid=$!; until [ -n \"$(ls -A " + frames +
                         " 2>/dev/null)\" ]; do sleep 0.02; done; kill -" + signal + " $pid; wait $pid; echo $? >" +
                         tmp.path("code");
    std::system(("timeout 120 sh -c '" + script + "'").c_str());
    EXPECT_EQ(testing::slurp(tmp.path("code")), std::to_string(code) + "\n") << signal;
    EXPECT_FALSE(std::filesystem::exists(frames)) << signal;
    EXPECT_NE(testing::slurp(tmp.path("stderr")).find("unfinished output file"), std::string::npos) << signal;
  }
}

}  // namespace
}  // namespace plumbago
