// The scene's stroke keys (Kalnins et al. 2002): "style": "strokes" with its effects, and "strokes" styles
// by preset or file, refused with the scene file and key when wrong.
#include <gtest/gtest.h>

#include "common/scene/scene.hpp"
#include "tests/support/temp_dir.hpp"

namespace plumbago {
namespace {

std::string refusal(const std::string& json, const std::string& dir) {
  try {
    parse_scene(json, "bad.json", dir);
  } catch (const SceneError& e) {
    return e.what();
  }
  return "accepted";
}

const char* kStrokeObject = R"("objects": [{"mesh": {"procedural": "cube"}, "style": "strokes"}])";

TEST(StrokeScene, StrokeObjectsBringTheirEffects) {
  Scene s = parse_scene(std::string("{") + kStrokeObject + "}", "s.json", ".");
  EXPECT_EQ(s.effects, (std::vector<std::string>{"basecoat", "strokes"}));
  Scene lines_only = parse_scene(std::string("{") + kStrokeObject + R"(, "effects": []})", "s.json", ".");
  EXPECT_EQ(lines_only.effects, std::vector<std::string>{"strokes"});
}

TEST(StrokeScene, StylesByPresetAndByFile) {
  testing::TempDir tmp;
  tmp.write("wide.json", R"({"width_px": 12, "texture": "ink"})");
  Scene s = parse_scene(
      std::string("{") + kStrokeObject + R"(, "strokes": {"crease": "charcoal", "silhouette": "wide.json"}})", "s.json",
      tmp.dir());
  EXPECT_EQ(s.strokes.crease.texture, StrokeTextureKind::Charcoal);
  EXPECT_EQ(s.strokes.silhouette.width_px, 12.0f);
  EXPECT_EQ(s.strokes.border.width_px, default_stroke_style().width_px);
}

TEST(StrokeScene, RefusalsNameTheSceneTheKeyAndTheStyle) {
  testing::TempDir tmp;
  tmp.write("huge.json", R"({"width_px": 500})");
  tmp.write("typo.json", R"({"widht_px": 5})");
  const std::map<std::string, std::vector<std::string>> cases = {
      {R"("strokes": {"crease": "nope"})", {"bad.json: /strokes/crease:", "nope"}},
      {R"("strokes": {"crease": "missing.json"})", {"bad.json: /strokes/crease:", "missing.json"}},
      {R"("strokes": {"crease": "huge.json"})", {"bad.json: /strokes/crease:", "huge.json", "/width_px"}},
      {R"("strokes": {"crease": "typo.json"})", {"bad.json: /strokes/crease:", "/widht_px"}},
      {R"("strokes": {"outline": "ink"})", {"bad.json: /strokes/outline: unknown key"}},
      {R"("strokes": {"crease": 3})", {"bad.json: /strokes/crease: expected a style name"}},
  };
  for (const auto& [body, needles] : cases) {
    std::string m = refusal(std::string("{") + kStrokeObject + ", " + body + "}", tmp.dir());
    for (const std::string& n : needles) EXPECT_NE(m.find(n), std::string::npos) << body << "\n gave: " << m;
  }
  EXPECT_NE(refusal(R"({"mesh": {"procedural": "cube"}, "effects": ["strokes"]})", tmp.dir()).find("no object has it"),
            std::string::npos);
}

}  // namespace
}  // namespace plumbago
