// Drawing on the model (Kalnins et al. 2002, "Drawing Strokes Directly on 3D Models", §3-§6):
// the strokes the artist draws in the viewer's window, in the stroke files' terms
// (common/strokes/stroke_file.hpp): a decal or a hatching group's stroke is projected onto
// the surface through the G-buffer of the view it was drawn in (common/strokes/decal.hpp),
// a crease or silhouette stroke is an offsets example that restyles the scene's lines.
// Strokes drawn in one view make one stroke file (a file holds one camera); a move of the
// camera starts the next. The scene shows its own stroke files, then these.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "common/scene/scene.hpp"
#include "common/strokes/decal.hpp"

namespace plumbago {

// What the artist asks for: the role, a style (preset or file; decals and hatching), a
// hatching group, whether it is free and whether mobile, and the points in the frame's pixels (origin
// bottom-left, docs/conventions.md) with their pressure.
struct DrawRequest {
  StrokeRole role = StrokeRole::Decal;
  std::string style = kDefaultDecalStyle;
  int group = 0;
  bool free = false, mobile = false;
  std::vector<DrawnPoint> points;
};

// `request` drawn in `scene`'s current view, checked as a stroke file's stroke is
// (parse_stroke_file: points, pressure, style, an example's chord). Throws SceneError
// naming "drawn stroke" and what is wrong.
DrawnStroke drawn_stroke(const Scene& scene, const DrawRequest& request);

// Where a decal or hatch landed: its polylines of surface points (projected through the
// G-buffer of its view, common/strokes/decal.hpp), and the object most of them lie on
// (kMissed for an example, which lies on no surface).
struct DrawnSurface {
  std::vector<std::vector<DecalPoint>> polylines;
  uint32_t object = kMissed;
};
// The surface of `projected`, `scene`'s objects in strokes style only.
DrawnSurface drawn_surface(const Scene& scene, const DecalSurface& projected);

class Drawing {
 public:
  // Adds `stroke`, drawn in `scene`'s view, lying on `surface`; drops what was undone.
  void add(const Scene& scene, DrawnStroke stroke, DrawnSurface surface = {});
  bool undo();  // whether there was a stroke to take back
  bool redo();
  void erase(size_t stroke);  // in the order drawn

  // The strokes drawn, in order, and the files they make: consecutive strokes of one view
  // in one file, its source the path save() wrote it to (before: "(drawn in view N, not
  // saved)", which names it in messages and is no file).
  size_t size() const { return drawn_.size(); }
  const DrawnStroke& stroke(size_t i) const { return drawn_.at(i).stroke; }
  uint32_t object(size_t i) const { return drawn_.at(i).surface.object; }
  // The decal or hatch whose surface passes nearest to window point `at` (px, origin
  // bottom-left) in `scene`'s current view, within `radius` px: the eraser's pick. Points
  // behind the near plane and surfaces hidden by others count alike.
  std::optional<size_t> stroke_near(const Scene& scene, glm::dvec2 at, double radius) const;
  std::vector<StrokeFile> files() const;
  // Whether every stroke is in a file save() wrote since the last change.
  bool saved() const { return saved_; }

  // Writes files() next to each other: `path` for the first, then path's stem with -2,
  // -3, ... (each whole, or not at all); returns their paths. A style file's path is
  // written relative to the stroke file's folder. Throws std::invalid_argument when
  // nothing is drawn.
  std::vector<std::string> save(const std::string& path, glm::dvec3 origin);

 private:
  struct Drawn {
    Camera camera;
    int width, height;
    DrawnStroke stroke;
    DrawnSurface surface;
  };
  void changed() { saved_ = false, paths_.clear(); }
  std::vector<Drawn> drawn_, undone_;
  std::vector<std::string> paths_;  // per file, where save() wrote it
  bool saved_ = true;
};

}  // namespace plumbago
