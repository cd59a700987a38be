#version 450 core
// The stroke ribbons (Kalnins et al. 2002, §4.1), expanded from their samples: step 6 of
// common/strokes/base_stroke.hpp, in float. Six vertices per sample j, the triangles
// (R_j, L_j, R_{j+1}), (R_{j+1}, L_j, L_{j+1}) of the segment to sample j + 1, or none where
// that segment is not drawn (the pen is up, or j is its run's last sample). Attributes are
// affine in the window.
struct Sample {  // gpu/strokes/stroke.cpp SampleRecord
  vec2 position;  // window px, offset applied
  float u, width, alpha;
  uint run, pen_down_after, pad;
};
struct Run {  // gpu/strokes/stroke.cpp RunRecord
  vec4 color_layer;
  uint first, count, cyclic, pad;  // cyclic: closed and drawn whole
};
layout(std430, binding = 0) readonly buffer Samples { Sample samples[]; };
layout(std430, binding = 1) readonly buffer Runs { Run runs[]; };
uniform vec2 window_size;
noperspective out vec2 uv;
noperspective out float alpha;
flat out vec3 color;
flat out float layer;

const float kDegenerate = 1e-9;  // px: shorter segments have no direction of their own

int first_sample, last_sample;  // of the run being drawn

// The segment j -> j + 1 is drawn.
bool drawn(int j) { return j >= first_sample && j < last_sample && samples[j].pen_down_after != 0u; }

// The left unit normal of segment k, or of the previous drawn segment of its piece when k is
// degenerate (the piece's first nondegenerate one's, before any); (0, 0) when the piece has none.
vec2 segment_normal(int k) {
  for (int i = k; drawn(i); --i) {
    vec2 d = samples[i + 1].position - samples[i].position;
    if (length(d) > kDegenerate) return normalize(vec2(-d.y, d.x));
  }
  for (int i = k + 1; drawn(i); ++i) {
    vec2 d = samples[i + 1].position - samples[i].position;
    if (length(d) > kDegenerate) return normalize(vec2(-d.y, d.x));
  }
  return vec2(0.0);
}

// Miter-free: the normalized sum of the normals of the drawn segments on either side of
// sample i (wrapping around a cyclic run); a hairpin's cancelling pair takes the previous one.
vec2 vertex_normal(int i, bool cyclic) {
  bool has_prev = drawn(i - 1) || (cyclic && i == first_sample);
  bool has_next = drawn(i) || (cyclic && i == last_sample);
  vec2 prev = has_prev ? segment_normal(i > first_sample ? i - 1 : last_sample - 1) : vec2(0.0);
  vec2 next = has_next ? segment_normal(i < last_sample ? i : first_sample) : vec2(0.0);
  vec2 sum = prev + next;
  return length(sum) > kDegenerate ? normalize(sum) : (has_prev ? prev : next);
}

void main() {
  int j = gl_VertexID / 6, corner = gl_VertexID % 6;
  Run run = runs[samples[j].run];
  first_sample = int(run.first);
  last_sample = int(run.first + run.count) - 1;
  color = run.color_layer.rgb;
  layer = run.color_layer.a;
  if (!drawn(j) || segment_normal(j) == vec2(0.0)) {  // no triangles: both outside the clip volume, at one point
    gl_Position = vec4(-2.0, -2.0, 0.0, 1.0);
    uv = vec2(0.0);
    alpha = 0.0;
    return;
  }
  const int kSample[6] = int[6](0, 0, 1, 1, 0, 1);   // R_j L_j R_j+1 | R_j+1 L_j L_j+1
  const float kSide[6] = float[6](0.0, 1.0, 0.0, 0.0, 1.0, 1.0);  // v: 0 right of travel, 1 left
  int i = j + kSample[corner];
  Sample q = samples[i];
  vec2 window = q.position + vertex_normal(i, run.cyclic != 0u) * (q.width * (kSide[corner] - 0.5));
  gl_Position = vec4(window / window_size * 2.0 - 1.0, 0.0, 1.0);
  uv = vec2(q.u, kSide[corner]);
  alpha = q.alpha;
}
