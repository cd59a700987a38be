// The stroke ribbons (Kalnins et al. 2002, §4.1), expanded from their samples: step 6 of
// common/strokes/base_stroke.hpp, in float. Six corners per sample j, the triangles
// (R_j, L_j, R_{j+1}), (R_{j+1}, L_j, L_{j+1}) of the segment to sample j + 1, or none where
// that segment is not drawn (the pen is up, or j is its run's last sample).
struct Sample {  // gpu/strokes/stroke.hpp SampleRecord
  vec2 position;  // window px, offset applied
  float u, width, alpha;
  uint run, pen_down_after, pad;
};
struct Run {  // gpu/strokes/stroke.hpp RunRecord
  vec4 color_layer;
  uint first, count, cyclic, pad;  // cyclic: closed and drawn whole
};
layout(std430, binding = 0) readonly buffer Samples { Sample samples[]; };
layout(std430, binding = 1) readonly buffer Runs { Run runs[]; };

const float kDegenerate = 1e-9;  // px: shorter segments have no direction of their own

struct Span {  // the samples of the run being drawn, first to last
  int first, last;
};

// The segment j -> j + 1 is drawn.
bool drawn(Span s, int j) { return j >= s.first && j < s.last && samples[j].pen_down_after != 0u; }

// The left unit normal of segment k, or of the previous drawn segment of its piece when k is
// degenerate (the piece's first nondegenerate one's, before any); (0, 0) when the piece has none.
vec2 segment_normal(Span s, int k) {
  for (int i = k; drawn(s, i); --i) {
    vec2 d = samples[i + 1].position - samples[i].position;
    if (length(d) > kDegenerate) return normalize(vec2(-d.y, d.x));
  }
  for (int i = k + 1; drawn(s, i); ++i) {
    vec2 d = samples[i + 1].position - samples[i].position;
    if (length(d) > kDegenerate) return normalize(vec2(-d.y, d.x));
  }
  return vec2(0.0);
}

// Miter-free: the normalized sum of the normals of the drawn segments on either side of
// sample i (wrapping around a cyclic run); a hairpin's cancelling pair takes the previous one.
vec2 vertex_normal(Span s, int i, bool cyclic) {
  bool has_prev = drawn(s, i - 1) || (cyclic && i == s.first);
  bool has_next = drawn(s, i) || (cyclic && i == s.last);
  vec2 prev = has_prev ? segment_normal(s, i > s.first ? i - 1 : s.last - 1) : vec2(0.0);
  vec2 next = has_next ? segment_normal(s, i < s.last ? i : s.first) : vec2(0.0);
  vec2 sum = prev + next;
  return length(sum) > kDegenerate ? normalize(sum) : (has_prev ? prev : next);
}

// One corner of the ribbons: its window position (px), (u, v) and alpha, the run it belongs
// to; `drawn` false where its sample's segment draws nothing.
struct Corner {
  vec2 window, uv;
  float alpha;
  uint run;
  bool drawn;
};

// Corner `index` % 6 of sample `index` / 6.
Corner ribbon_corner(int index) {
  const int kSample[6] = int[6](0, 0, 1, 1, 0, 1);                // R_j L_j R_j+1 | R_j+1 L_j L_j+1
  const float kSide[6] = float[6](0.0, 1.0, 0.0, 0.0, 1.0, 1.0);  // v: 0 right of travel, 1 left
  int j = index / 6, corner = index % 6;
  uint r = samples[j].run;
  Span span = Span(int(runs[r].first), int(runs[r].first + runs[r].count) - 1);
  if (!drawn(span, j) || segment_normal(span, j) == vec2(0.0)) return Corner(vec2(0.0), vec2(0.0), 0.0, r, false);
  int i = j + kSample[corner];
  Sample q = samples[i];
  vec2 n = vertex_normal(span, i, runs[r].cyclic != 0u);
  return Corner(q.position + n * (q.width * (kSide[corner] - 0.5)), vec2(q.u, kSide[corner]), q.alpha, r, true);
}
