// Scenes: what to draw, from where, in which styles, with which effects and parameters.
// The file format is documented in docs/scene-format.md and scenes/scene.schema.json.
#pragma once

#include <cmath>
#include <cstdint>
#include <glm/glm.hpp>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "common/core/params.hpp"
#include "common/mesh/mesh.hpp"
#include "common/scene/animation.hpp"
#include "common/scene/camera.hpp"
#include "common/strokes/stroke_file.hpp"
#include "common/strokes/stroke_style.hpp"
#include "common/util/image.hpp"

namespace plumbago {

// Which pipeline draws an object: the pencil effects (Lee et al. 2006), sketchy drawing (Nienhaus & Döllner 2004),
// or stroke-based rendering (Kalnins et al. 2002). `Shaded` objects are drawn by the pencil effects.
enum class Style { Pencil, Sketchy, Shaded, Strokes };
// The scene file's names of the styles, in enum order: pencil, sketchy, shaded, strokes.
const std::vector<std::string>& style_names();

struct SceneObject {
  std::shared_ptr<const Mesh> mesh;
  glm::mat4 transform{1.0f};  // object to world, relative to Scene::origin
  Style style = Style::Pencil;
  glm::vec3 color{1.0f};
  bool flat = false;  // shading normals = face normals
};

// The stroke style of each kind of feature line of the stroke objects (Kalnins et al. 2002, §4.1;
// presets in styles/strokes, common/strokes/stroke_style.hpp). Scene key "strokes".
struct StrokeStyles {
  StrokeStyle crease = default_stroke_style(), border = default_stroke_style(), silhouette = default_stroke_style();
  // The offset examples drawn in the scene's stroke files (roles "crease" and "silhouette",
  // common/strokes/stroke_file.hpp drawn_offsets), which replace the styles' own: creases and
  // borders take the crease examples. Several are rubber-stamped in turn (run after run
  // along a path) or make one Markov chain (Kalnins et al. 2002, §4.3, §5, App. A).
  std::vector<OffsetExample> crease_examples, silhouette_examples;
};

struct Light {
  glm::vec3 direction{0, 0, 1};  // world space, from the surface towards the light
  float intensity = 1.0f;
};

// Every position in a Scene (object transforms, camera) is relative to `origin`, the world
// point at the center of the objects' bounding box: both backends render in these
// coordinates, so that a scene's image and parity do not depend on where it sits in the
// world (float at 1e6 resolves 0.06). The file's world coordinates are read in double and
// made relative before they become float.
struct Scene {
  std::string source;  // scene file path or "builtin:<name>"
  std::vector<SceneObject> objects;
  glm::dvec3 origin{0.0};  // world space
  Camera camera;
  std::vector<Light> lights;
  bool lights_follow_camera = false;  // the file gave no lights: default_lights(camera)
  int width = 800, height = 800;
  uint32_t seed = 1;
  std::vector<std::string> effects{"contours"};
  ParamSet params;
  StrokeStyles strokes;
  std::optional<Animation> animation;    // a camera path; none: one frame
  int frame = 0;                         // the frame of `animation` this scene shows (scene_at_frame)
  Camera path_start;                     // with frame > 0: the path's first camera (frame_camera)
  std::vector<StrokeFile> stroke_files;  // the artist's strokes (Kalnins et al. 2002, §3, §4.5), key "stroke_files"
};

// A scene refused: the message names the file and the JSON path of the offending key.
struct SceneError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// Loads a scene file (or a built-in scene, "builtin:NAME"); relative mesh paths resolve
// against the scene file's folder.
Scene load_scene(const std::string& path);
// The JSON text a scene is read from: its file, or the document of a built-in scene
// ("builtin:NAME"). Throws SceneError when the file cannot be read.
std::string scene_text(const std::string& source);
// The folder relative paths of `source`'s document resolve against.
std::string scene_folder(const std::string& source);
// Writes `scene` as a scene file that load_scene reads back to the same scene: the
// document it was read from (scene_text) with its camera, lights, resolution, seed,
// effects, parameters and object styles replaced by the scene's own and its relative
// paths rebased on `path`'s folder. Leaves no partial file; throws SceneError.
void save_scene(const Scene& scene, const std::string& path);
// The crease and silhouette examples (StrokeStyles' *_examples) made anew from the scene's
// stroke files: what loading does, and what a change to them (drawing in the viewer) needs.
void set_drawn_examples(Scene& scene);
// Parses scene JSON text; `source` names it in messages, `base_dir` resolves paths.
Scene parse_scene(const std::string& json_text, const std::string& source, const std::string& base_dir);

// Built-in procedural scenes (no files needed): "torus", "sphere", "cad".
Scene builtin_scene(const std::string& name);
std::vector<std::string> builtin_scene_names();

// An effect that draws only the objects of one style (Nienhaus & Döllner 2004; Kalnins et al. 2002; EffectDef::styled):
// "sketchy" the sketchy objects, "strokes" and "basecoat" the stroke objects. A scene
// lists one only when an object has its style; the `automatic` ones, without which those
// objects are not drawn at all ("sketchy", "strokes"), are on by themselves then.
struct StyleEffect {
  Style style;
  bool automatic;
};
const StyleEffect* style_effect(const std::string& effect);  // null for the other effects
bool has_style(const Scene& scene, Style style);
// Makes the effects agree with the objects' styles as a scene file must: drops the
// effects whose style no object has, adds the automatic ones whose style one has.
void match_effects_to_styles(Scene& scene);

// The pixels that `scene`'s objects can cover (the bounding rectangle of their projected
// vertices), grown by `margin` pixels and clipped to the window; the whole window when a
// vertex lies behind the eye. Outside it the sketch's maps hold their background values and the
// composite draws nothing, so the GPU skips it (a bound, not a stage: no formula changes).
PixelRect covered_rect(const Scene& scene, int width, int height, float margin);
// covered_rect's work before its margin, for a frame to do once where several passes ask:
// the window rectangle of the projected vertices at a size.
struct WindowBounds {
  glm::vec2 lo{INFINITY}, hi{-INFINITY};  // empty: no object
  bool behind_eye = false;                // a vertex lies behind the eye: the whole window
};
WindowBounds window_bounds(const Scene& scene, int width, int height);
PixelRect covered_rect(const WindowBounds& bounds, int width, int height, float margin);
// Where a window-space filter of the given pixel radius over the G-buffer can differ from
// its value on the background: covered_rect at the scene's size grown by the radius and a
// pixel to spare. The GPU runs such passes only there (edge detection and the sketchy
// maps: radius 1; the pencil interior: 0) and clears the rest to the background value.
PixelRect filter_rect(const Scene& scene, int radius);
// The same from the scene's window_bounds at its size.
PixelRect filter_rect(const WindowBounds& bounds, const Scene& scene, int radius);

// The lights of a scene file without "lights": one over the camera's left shoulder.
std::vector<Light> default_lights(const Camera& camera);

// World-space bounding sphere of all objects.
void scene_bounds(const Scene& scene, glm::vec3& center, float& radius);

}  // namespace plumbago
