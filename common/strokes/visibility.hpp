// Visibility of stroke samples (Kalnins et al. 2002 §4.6), from the ID image.
//
// Each path of common/strokes/strokes.hpp is sampled every `strokes.vis_step_px` pixels of window
// arc length from its start (an open path also at its end), where it runs within 4 px of
// the window; where it leaves or enters that, one sample marks the edge (hidden). A sample at window position
// p, in pixel floor(p), is visible when some pixel of the 3x3 box around it (5x5 for hatches) holds
//   - a silhouette: its path key, with an arc-length byte within
//     ceil(2 max(2, 256 / L_px)) of its own floor(255 s / L) (around the seam of a
//     closed path, the shorter way);
//   - a crease or border: its path key, or the key of a front-facing face next to it; under
//     strokes.crease_under_silhouettes also where its own pixel holds one of them in the key
//     image before the silhouettes' quads (common/strokes/id_image.hpp: a silhouette's quad,
//     3 px wide and drawn nearer, hides a crease running beside it);
//   - a decal (a stroke fixed on the surface, Kalnins et al. 2002, §3, §4.5, common/strokes/decal.hpp): the key of the
//     face of the nearer of its segment's two path points;
//   - a hatch (Kalnins et al. 2002, §6, common/strokes/hatching.hpp), in the 5x5 box (2 px): the key of the face of
//     either of its segment's two path points. ("a face of its group", docs/stages.md: a hatch lies
//     on the faces its own points were projected onto, the interpolated ones too.)
// Back-facing silhouettes are not in the ID image, so never visible.
//
// Where two neighbouring samples disagree, the change is bisected along the path (new
// samples at the midpoints, tested the same way) until it is located within 1 px
// (Kalnins et al. 2002, §4.1). What is visible then makes the runs the strokes draw.
//
// `sample_visible` is the one test both backends run. The reference samples, bisects and
// makes the runs here, calling its batch test through `visible_runs`; the GPU does all of it
// in compute shaders (shaders/strokes/visibility.comp, the formula written twice), one
// invocation per segment, sample or change, and reads back, once, the totals and the runs'
// ends.
#pragma once

#include <cstdint>
#include <functional>
#include <vector>

#include <glm/glm.hpp>

#include "common/core/stage.hpp"
#include "common/strokes/id_image.hpp"
#include "common/strokes/strokes.hpp"
#include "common/util/image.hpp"

namespace plumbago {

enum SampleKind : uint32_t { kCreaseSample = 0, kSilhouetteSample = 1, kDecalSample = 2, kHatchingSample = 3 };

// One sample as both backends read it (std430 layout: 32 bytes).
struct VisibilitySample {
  glm::vec2 window;
  uint32_t kind;         // SampleKind
  uint32_t key;          // the path key
  uint32_t faces[2];     // crease or border: front-facing adjacent faces (0: none); decal: its face, 0;
                         // hatch: its segment's two faces
  uint32_t byte;         // silhouette: floor(255 s / L)
  uint32_t byte_window;  // silhouette: ceil(2 max(2, 256 / L_px)), at most 255; bit 8: a closed path
};

// The segment of `path` (from point k to k + 1) at window arc length s.
size_t segment_at(const WindowPath& path, double s);

// The world point of `path` at window arc length s (perspective-correct along its segment).
glm::dvec3 world_at(const WindowPath& path, double s);

// The sample of `path` at window arc length s.
VisibilitySample sample_at(const WindowPath& path, double s);

// The Kalnins et al. 2002, §4.6 test of one sample against the ID image's keys.
bool sample_visible(const ImageU32& keys, const VisibilitySample& s);
// The same, and under strokes.crease_under_silhouettes (`crease_keys`: the key image before
// the silhouettes' quads, else none) a crease or border sample's own pixel there.
bool sample_visible(const ImageU32& keys, const ImageU32* crease_keys, const VisibilitySample& s);

// A visible stretch of a path, in window arc length.
struct VisibleRun {
  uint32_t path;                      // index in WindowLines::paths
  double s0, s1;                      // s1 > s0; a closed path's run may pass its seam (s1 beyond its length)
  bool closed;                        // the whole closed path
  bool occluded_start, occluded_end;  // the end is where the path goes out of sight
  // The path's window polyline from s0 to s1; empty in the GPU's frame, which makes it on the
  // GPU (gpu/strokes/stroke_samples.hpp).
  std::vector<glm::dvec2> window;
};

using SampleTest = std::function<std::vector<uint8_t>(const std::vector<VisibilitySample>&)>;

struct Visibility {
  size_t samples = 0;          // the first round's
  std::vector<uint8_t> flags;  // the first round's, path after path (the GPU: only when dumping)
  std::vector<VisibleRun> runs;
};

// Samples every path, tests them with `test`, bisects the changes and returns the runs.
Visibility visible_runs(const WindowLines& lines, const StrokesParams& p, const SampleTest& test);

// At least as many first-round samples as either backend takes of path p: per segment
// within the window's 4 px margin, the step's multiples along that stretch, one more where
// the arc lengths of neighbouring segments overlap (the backends round a segment's end each
// their own way), and its two edge samples unless both its ends are clear of the margin's
// edges; per path its end, s = 0 and a segment the GPU's clip keeps where the reference's
// does not. Both
// backends size their memory by it; a line far off the window costs nothing off it.
double first_round_bound(const WindowPath& p, double step, double width, double height);

// The length of path p within the window's 4 px margin, where its samples are: its visible
// runs lie there, so they are at most this long together.
double length_in_margin(const WindowPath& p, double width, double height);

// The run of path i (index `i` in WindowLines::paths) from s0 to s1, with its window polyline.
VisibleRun run_along(const WindowPath& path, uint32_t i, double s0, double s1, bool closed, bool occluded_start,
                     bool occluded_end);

// A run as the GPU lists it, ends and flags as in run_tables: an end that is not
// occluded is its path's own end (0 or the length), taken exactly. Its window polyline is
// made where `with_window` (the GPU's frame makes its own: gpu/strokes/stroke_samples.hpp).
VisibleRun run_from_row(const WindowPath& path, uint32_t i, double s0, double s1, uint32_t flags,
                        bool with_window = true);

// The flags as the stage's output image: one texel per sample, row after row of 1024.
Image flags_image(const std::vector<uint8_t>& flags);
// The runs as two tables: (path + 1, closed + 2 occluded start + 4 occluded end) and (s0, s1).
std::pair<Image, Image> run_tables(const std::vector<VisibleRun>& runs);

inline constexpr Buffer kFlags{"visibility.flags"};
inline constexpr Buffer kRunPaths{"visibility.run_paths"};
inline constexpr Buffer kRunEnds{"visibility.run_ends"};
inline constexpr Slot<Visibility> kVisibleRuns{"visibility.runs"};

struct VisibilityStage {
  using Params = TypeList<>;  // reads strokes.*, which the ID image declares
  static StageDesc describe() {
    return {.name = "visibility",
            .kind = StageKind::Frame,
            .doc = "visibility of stroke samples from the ID image (Kalnins et al. 2002, §4.6)",
            .params = {"strokes"},
            .inputs = {{.handle = kIds}, {.handle = kCreaseIds}, {.handle = kWindowLines}},
            .outputs = {{.handle = kFlags,
                         .texel = Texel::Unorm8,
                         .doc = "1 where a first-round sample is visible: one texel per sample, 1024 a row",
                         .tolerance_why = "fed the same ID image and paths: the same integer test, at positions "
                                          "both take in double and round to float"},
                        {.handle = kRunPaths,
                         .channels = 2,
                         .doc = "per visible run: (path + 1, closed + 2 occluded start + 4 occluded end)",
                         .tolerance_why = "integers from the same flags: exact"},
                        {.handle = kRunEnds,
                         .channels = 2,
                         .doc = "per visible run: (s0, s1), its ends in window arc length (px)",
                         .tolerance = 1,
                         .tolerance_why = "each backend locates a change within 0.5 px of where its tests change "
                                          "(Kalnins et al. 2002, §4.1: 1 px)"},
                        {.handle = kVisibleRuns,
                         .channels = 0,
                         .texel = Texel::Host,
                         .doc = "the visible runs of every path, ends bisected to 1 px (CPU; the GPU keeps its own, "
                                "which a dump reads back)"}},
            .effects = {"strokes"}};
  }
};

}  // namespace plumbago
