// Scenes: what to draw, from where, in which styles, with which effects and parameters.
// The file format is documented in docs/scene-format.md and scenes/scene.schema.json.
#pragma once

#include <cstdint>
#include <glm/glm.hpp>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "common/camera.hpp"
#include "common/image.hpp"
#include "common/mesh.hpp"
#include "common/params.hpp"
#include "common/stroke_style.hpp"

namespace plumbago {

// Which pipeline draws an object: the pencil effects (SPEC 2), sketchy drawing (SPEC 3),
// or stroke-based rendering (SPEC 4). `Shaded` objects are drawn by the pencil effects.
enum class Style { Pencil, Sketchy, Shaded, Strokes };

struct SceneObject {
  std::shared_ptr<const Mesh> mesh;
  glm::mat4 transform{1.0f};  // object to world
  Style style = Style::Pencil;
  glm::vec3 color{1.0f};
  bool flat = false;          // shading normals = face normals
};

// The stroke style of each kind of feature line of the stroke objects (SPEC 4.6-4.7;
// presets in styles/strokes, common/stroke_style.hpp). Scene key "strokes".
struct StrokeStyles {
  StrokeStyle crease = default_stroke_style(), border = default_stroke_style(), silhouette = default_stroke_style();
};

struct Light {
  glm::vec3 direction{0, 0, 1};  // world space, from the surface towards the light
  float intensity = 1.0f;
};

struct Scene {
  std::string source;  // scene file path or "builtin:<name>"
  std::vector<SceneObject> objects;
  Camera camera;
  std::vector<Light> lights;
  int width = 800, height = 800;
  uint32_t seed = 1;
  std::vector<std::string> effects{"contours"};
  ParamSet params;
  StrokeStyles strokes;
};

// A scene refused: the message names the file and the JSON path of the offending key.
struct SceneError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// Loads a scene file; relative mesh paths resolve against the scene file's folder.
Scene load_scene(const std::string& path);
// Parses scene JSON text; `source` names it in messages, `base_dir` resolves paths.
Scene parse_scene(const std::string& json_text, const std::string& source, const std::string& base_dir);

// Built-in procedural scenes (no files needed): "torus", "sphere", "cad".
Scene builtin_scene(const std::string& name);
std::vector<std::string> builtin_scene_names();

// The pixels that `scene`'s objects can cover (the bounding rectangle of their projected
// vertices), grown by `margin` pixels and clipped to the window; the whole window when a
// vertex lies behind the eye. Outside it the sketch's maps hold their background values and the
// composite draws nothing, so the GPU skips it (a bound, not a stage: no formula changes).
PixelRect covered_rect(const Scene& scene, int width, int height, float margin);
// Where a window-space filter of the given pixel radius over the G-buffer can differ from
// its value on the background: covered_rect at the scene's size grown by the radius and a
// pixel to spare. The GPU runs such passes only there (edge detection and the sketchy
// maps: radius 1; the pencil interior: 0) and clears the rest to the background value.
PixelRect filter_rect(const Scene& scene, int radius);

// World-space bounding sphere of all objects.
void scene_bounds(const Scene& scene, glm::vec3& center, float& radius);

}  // namespace plumbago
