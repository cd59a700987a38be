// The stroke ribbons (Kalnins et al. 2002, §4.1), expanded from their samples: step 6 of
// common/strokes/base_stroke.hpp, in float. Once a run, by the invocation that wrote its
// samples (shaders/strokes/stroke_samples.comp), each sample's vertex normal and whether the
// segment to the next one draws (put_ribbon_normals). Then six corners per sample j, the
// triangles (R_j, L_j, R_{j+1}), (R_{j+1}, L_j, L_{j+1}) of the segment to sample j + 1, or
// none where that segment is not drawn (the pen is up, j is its run's last sample, or its
// piece has no direction).
struct Sample {  // gpu/strokes/stroke.hpp SampleRecord
  vec2 position;  // window px, offset applied
  float u, width, alpha;
  uint run, pen_down_after;
  uint ribbon;  // put_ribbon_normals: the segment to the next sample draws
  vec2 normal;  // put_ribbon_normals: the vertex normal
};
struct Run {  // gpu/strokes/stroke.hpp RunRecord
  vec4 color_layer;
  uint first, count, cyclic, pad;  // cyclic: closed and drawn whole
};
// Written where RIBBON_NORMALS is defined (put_ribbon_normals), read elsewhere.
#if defined(RIBBON_NORMALS)
#define RIBBON_ACCESS
#else
#define RIBBON_ACCESS readonly
#endif
layout(std430, binding = 0) RIBBON_ACCESS buffer Samples { Sample samples[]; };
layout(std430, binding = 1) RIBBON_ACCESS buffer Runs { Run runs[]; };

const float kDegenerateSegment = 1e-9;  // px: shorter segments have no direction of their own

struct SampleSpan {  // the samples of the run being drawn, first to last
  int first, last;
};

// The segment j -> j + 1 is drawn.
bool drawn(SampleSpan s, int j) { return j >= s.first && j < s.last && samples[j].pen_down_after != 0u; }

// The left unit normal of segment k, or of the previous drawn segment of its piece when k is
// degenerate (the piece's first nondegenerate one's, before any); (0, 0) when the piece has none.
vec2 segment_normal(SampleSpan s, int k) {
  for (int i = k; drawn(s, i); --i) {
    vec2 d = samples[i + 1].position - samples[i].position;
    if (length(d) > kDegenerateSegment) return normalize(vec2(-d.y, d.x));
  }
  for (int i = k + 1; drawn(s, i); ++i) {
    vec2 d = samples[i + 1].position - samples[i].position;
    if (length(d) > kDegenerateSegment) return normalize(vec2(-d.y, d.x));
  }
  return vec2(0.0);
}

// Miter-free: the normalized sum of the normals of the drawn segments on either side of
// sample i (wrapping around a cyclic run); a hairpin's cancelling pair takes the previous one.
vec2 vertex_normal(SampleSpan s, int i, bool cyclic) {
  bool has_prev = drawn(s, i - 1) || (cyclic && i == s.first);
  bool has_next = drawn(s, i) || (cyclic && i == s.last);
  vec2 prev = has_prev ? segment_normal(s, i > s.first ? i - 1 : s.last - 1) : vec2(0.0);
  vec2 next = has_next ? segment_normal(s, i < s.last ? i : s.first) : vec2(0.0);
  vec2 sum = prev + next;
  return length(sum) > kDegenerateSegment ? normalize(sum) : (has_prev ? prev : next);
}

// One corner of the ribbons: its window position (px), (u, v) and alpha, the run it belongs
// to; `drawn` false where its sample's segment draws nothing.
struct Corner {
  vec2 window, uv;
  float alpha;
  uint run;
  bool drawn;
};

#if defined(RIBBON_NORMALS)
// Run r's samples' vertex normals, and which of their segments draw, from their positions
// and pen: once per run, before its corners.
void put_ribbon_normals(uint r) {
  SampleSpan span = SampleSpan(int(runs[r].first), int(runs[r].first + runs[r].count) - 1);
  bool cyclic = runs[r].cyclic != 0u;
  for (int i = span.first; i <= span.last; ++i) {
    samples[i].normal = vertex_normal(span, i, cyclic);
    samples[i].ribbon = drawn(span, i) && segment_normal(span, i) != vec2(0.0) ? 1u : 0u;
  }
}
#endif

// Corner `index` % 6 of sample `index` / 6.
Corner ribbon_corner(int index) {
  const int kSample[6] = int[6](0, 0, 1, 1, 0, 1);                // R_j L_j R_j+1 | R_j+1 L_j L_j+1
  const float kSide[6] = float[6](0.0, 1.0, 0.0, 0.0, 1.0, 1.0);  // v: 0 right of travel, 1 left
  int j = index / 6, corner = index % 6;
  uint r = samples[j].run;
  if (samples[j].ribbon == 0u) return Corner(vec2(0.0), vec2(0.0), 0.0, r, false);
  Sample q = samples[j + kSample[corner]];
  return Corner(q.position + q.normal * (q.width * (kSide[corner] - 0.5)), vec2(q.u, kSide[corner]), q.alpha, r,
                true);
}
