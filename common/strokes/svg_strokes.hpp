// Strokes drawn in SVG over a rendering (Kalnins et al. 2002, §3, §4.5): how a user makes a stroke file
// without a tablet (`plumbago strokefile`, docs/scene-format.md).
//
// Read: every <polyline points="..."> and every <path d="..."> made of straight segments
// (M, L, H, V, Z, absolute or relative; each M starts another stroke). Per element:
//   - pressure: `data-pressure` (one number in [0, 1] for every point, or one per point),
//     else its stroke width (the `stroke-width` attribute or style property) over the
//     widest stroke width of the drawing, else 1;
//   - `data-role` (decal, crease, silhouette, hatching), `data-style` (the preset or style
//     file of decals and hatching), `data-group` and `data-free="true"` (hatching): override
//     the command's --role, --style, --group, --free.
// Coordinates are the SVG's user units: the root's viewBox (else its width and height,
// else the window) is mapped onto the window, y flipped (SVG's origin is top-left, the
// window's bottom-left, docs/conventions.md). Curves (C, S, Q, T, A) and `transform` attributes are
// refused, naming the element: flatten them first.
#pragma once

#include <string>
#include <vector>

#include "common/strokes/stroke_file.hpp"

namespace plumbago {

struct SvgStrokeDefaults {
  StrokeRole role = StrokeRole::Decal;
  std::string style;  // empty: the stroke file names none
  int group = 0;      // hatching
  bool free = false;  // hatching: a free group
};

// The strokes of an SVG document in a width x height window; throws std::invalid_argument
// naming `source` and the element.
std::vector<DrawnStroke> svg_strokes(const std::string& svg, const std::string& source, int width, int height,
                                     const SvgStrokeDefaults& defaults);

}  // namespace plumbago
