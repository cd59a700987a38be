// Strokes drawn in SVG over a rendering (Kalnins et al. 2002, §3, §4.5): how a user makes a stroke file
// without a tablet (`plumbago strokefile`, docs/scene-format.md).
//
// Read: every <polyline points="..."> and every <path d="..."> made of straight segments
// (M, L, H, V, Z, absolute or relative; each M starts another stroke). Per element:
//   - pressure: `data-pressure` (one number in [0, 1] for every point, or one per point),
//     else its stroke width (the `stroke-width` attribute or style property) over the
//     widest stroke width of the drawing, else 1;
//   - `data-role` (decal, crease, silhouette, hatching), `data-style` (the preset or style
//     file of decals and hatching), `data-group`, `data-free="true"` and `data-mobile="true"`
//     (hatching): override the command's --role, --style, --group, --free, --mobile.
// Coordinates are the SVG's user units: the root's viewBox (else its width and height,
// else the window) is mapped onto the window, y flipped (SVG's origin is top-left, the
// window's bottom-left, docs/conventions.md). Curves (C, S, Q, T, A) and `transform` attributes are
// refused, naming the element: flatten them first. Other elements are not read.
//
// The XML is parsed by pugixml; numbers, lists and path data by the scanner of
// common/strokes/svg_numbers.hpp (linear, no recursion). Every refusal names the file, the
// element (its id when it has one, and its index among the svg, g, polyline and path
// elements) and the attribute: `drawing.svg: <polyline id="a"> #3: points: 'x1' is not a
// number`; or the line and column of malformed XML. Refused besides: a number that is not one
// (NaN, Inf, garbage) or beyond double range, a viewBox other than 4 numbers, a missing
// `points` or `d`, a point beyond a stroke file's bound (kMaxDrawnPixel), more points than a
// stroke file may hold (kMaxDrawnPoints), a crease or silhouette that makes no offsets
// example (offsets_example_fault, e.g. of zero length), a style that does not load, a
// data-group outside 0..kMaxHatchingGroup: what a stroke file would refuse is refused here,
// naming the element.
#pragma once

#include <stdexcept>
#include <string>
#include <vector>

#include "common/strokes/stroke_file.hpp"

namespace plumbago {

struct SvgStrokeDefaults {
  StrokeRole role = StrokeRole::Decal;
  std::string style;            // empty: the stroke file names none
  int group = 0;                // hatching
  bool free = false;            // hatching: a free group
  bool mobile = false;          // hatching: a mobile group (Kalnins et al. 2002, §6.3)
  std::string style_dir = ".";  // where style files named by a relative path are (the stroke file's folder)
};

// A refused drawing: the message names the file, the element and the attribute.
struct SvgError : std::invalid_argument {
  using std::invalid_argument::invalid_argument;
};

// The strokes of an SVG document in a width x height window, their styles loaded; throws
// SvgError naming `source`, the element and the attribute.
std::vector<DrawnStroke> svg_strokes(const std::string& svg, const std::string& source, int width, int height,
                                     const SvgStrokeDefaults& defaults);

}  // namespace plumbago
