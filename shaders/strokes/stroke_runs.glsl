// The visible runs as the stroke samples' steps read them (gpu/strokes/run_styles.hpp RunInput,
// OffsetInput; std430): each run's polyline, style and offsets example, made on the GPU
// (shaders/strokes/run_inputs.comp) or, for tests, given.
struct RunIn {  // gpu/strokes/run_styles.hpp RunInput
  vec4 color_layer;
  uint first_point, point_count, first_offset, offset_count;
  double example_length;  // the offsets example's L_drawn (no offsets: offset_count 0)
  float width, alpha, taper, fade, halo, flare, sample_px, period;
  uint flags;       // kClosed | kOccludedStart | kOccludedEnd | kPressureWidth | kPressureAlpha | kRepeats | kUnscaled
  uint knot_count;  // its brush parameter's knots, after its points (none: t = s)
};
struct Offset {  // gpu/strokes/run_styles.hpp OffsetInput
  double t, displacement, pressure;
  uint pen_up, pad;
};
const uint kClosed = 1u, kOccludedStart = 2u, kOccludedEnd = 4u, kPressureWidth = 8u, kPressureAlpha = 16u;
const uint kRepeats = 32u;  // the offsets example repeats (common/strokes/stroke_style.hpp OffsetExample::repeats)
const uint kUnscaled = 64u;  // and is not scaled to the run (OffsetExample::scales false)
