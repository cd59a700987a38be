// Stroke files (Kalnins et al. 2002 §3, §4.3): the artist's strokes, drawn
// over a rendering instead of on a tablet. A JSON document:
//   {"camera": {"eye": [x, y, z], "target": [x, y, z], "up": [x, y, z], "fov_deg": F,
//               "near": N, "far": F},          world coordinates of the scene file
//    "resolution": [W, H],                     the window the strokes were drawn in
//    "style": PRESET_OR_FILE,                  optional: the decals' style where a stroke names none
//    "strokes": [{"role": ROLE, "points": [[x, y, pressure], ...],
//                 "style": PRESET_OR_FILE,     optional, decals and hatching
//                 "group": G,                  hatching only: the group's number (>= 0)
//                 "free": true,                hatching only, optional: a free group (Kalnins et al. 2002, §6)
//                 "mobile": true}, ...]}       hatching only, optional: a mobile group (§6.3,
//                                              common/strokes/mobile_hatching.hpp)
// Points are window pixels of docs/conventions.md (origin bottom-left), pressure in [0, 1]; a stroke
// has 2 points or more. ROLE is
//   - "decal": a stroke fixed on the surface where it was drawn (common/strokes/decal.hpp);
//   - "crease", "silhouette": an offset example for that kind of line (Kalnins et al. 2002, §4.3, §5, App. A;
//     drawn_offsets below): the scene's creases (and borders) or silhouettes take the
//     examples of its stroke files in place of their style's;
//   - "hatching": a stroke of hatching group G (Kalnins et al. 2002, §6, common/strokes/hatching.hpp): structured
//     unless "free" says otherwise, stationary unless "mobile" says otherwise; a group's
//     strokes are all structured or all free, all mobile or all stationary.
// Every role is used.
// A scene lists its stroke files under "stroke_files" (docs/scene-format.md); a refusal
// throws SceneError naming the stroke file and the JSON path, as scene files do.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "common/scene/camera.hpp"
#include "common/strokes/stroke_style.hpp"

namespace plumbago {

enum class StrokeRole { Decal, Crease, Silhouette, Hatching };
// The file's names of the roles, in enum order.
const std::vector<std::string>& stroke_role_names();

struct DrawnPoint {
  glm::dvec2 window;  // px, origin bottom-left
  double pressure = 1;
};

struct DrawnStroke {
  StrokeRole role = StrokeRole::Decal;
  std::vector<DrawnPoint> points;
  std::string style_name;            // as the file gives it (the stroke's, else the file's); may be empty
  std::optional<StrokeStyle> style;  // decals, hatching: loaded from style_name (ink when neither names one)
  int group = -1;                    // hatching: the group
  bool free = false;                 // hatching: a free group's stroke (else structured)
  bool mobile = false;               // hatching: a mobile group's stroke (Kalnins et al. 2002, §6.3)
};

struct StrokeFile {
  std::string source;  // path as read
  Camera camera;       // relative to the scene's origin, as every camera of a Scene
  int width = 0, height = 0;
  std::string style;  // the file's "style", or empty
  std::vector<DrawnStroke> strokes;
};

// A crease or silhouette example as Kalnins et al.'s (2002, §4.3, App. A) offset list, against its chord (the segment
// from its first point to its last, of length L_drawn): per point, t = its projection on
// the chord over L_drawn (never decreasing: a stroke that turns back holds its t), the
// displacement = its signed distance from the chord, positive to the left of the direction
// of travel (the screen normal of common/strokes/stroke_style.hpp), and its pressure. Throws
// SceneError naming `source` and the stroke when offsets_example_fault finds one.
OffsetExample drawn_offsets(const DrawnStroke& stroke, const std::string& source);
// Empty when `stroke` makes an offsets example, else why not: its ends are under 1 px
// apart (a stroke of zero length among them) or a displacement passes +-1000 px. A
// stroke file's crease and silhouette strokes are checked when it is read.
std::string offsets_example_fault(const DrawnStroke& stroke);

// A drawn point's bound, px from the window's origin; a hatching group's largest number.
inline constexpr double kMaxDrawnPixel = 1e6;
inline constexpr int kMaxHatchingGroup = 1000000;
// The most points of one stroke file or drawing: 50 times the largest of scenes/drawn
// (5000), and few enough that `plumbago strokefile` holds them in a few hundred MB
// (measured: 0.23 GB at the bound) and writes a file within the input files' bound
// (common/util/input_file.hpp; at most 62 B a point).
inline constexpr size_t kMaxDrawnPoints = 250000;

// The style of decals and hatching where neither the stroke nor the file names one.
inline constexpr const char* kDefaultDecalStyle = "ink";

// Reads a stroke file; `origin` is the scene's (Scene::origin), `base_dir` resolves style
// files given by relative path. Throws SceneError naming `source` and the JSON path.
StrokeFile parse_stroke_file(const std::string& text, const std::string& source, const std::string& base_dir,
                             glm::dvec3 origin);
StrokeFile load_stroke_file(const std::string& path, glm::dvec3 origin);

// The document of a stroke file (what parse_stroke_file reads back), the camera made
// absolute again with `origin`.
std::string stroke_file_json(const StrokeFile& file, glm::dvec3 origin);

}  // namespace plumbago
