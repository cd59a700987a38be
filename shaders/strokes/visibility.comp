#version 450 core
// Visibility of stroke samples (Kalnins et al. 2002, §4.6), one invocation per sample: the test of
// common/strokes/visibility.cpp (sample_visible) on the ID image's keys.
layout(local_size_x = 64) in;

struct Sample {
  vec2 window;
  uint kind;  // 0 crease or border, 1 silhouette, 2 decal, 3 hatch (common/strokes/visibility.hpp SampleKind)
  uint key;
  uint faces[2];
  uint byte_value;
  uint byte_window;  // at most 255; bit 8: a closed path (bytes compared around the seam)
};
layout(std430, binding = 0) readonly buffer Samples { Sample samples[]; };
layout(std430, binding = 1) writeonly buffer Flags { uint flags[]; };
uniform usampler2D ids;  // (key >> 16, key & 0xffff)
uniform uint sample_count;
uniform uint first_sample;  // of this dispatch (a batch may take several: 65535 groups at most each)

bool holds(uint value, Sample s) {
  if (value == 0u) return false;
  if (s.kind == 2u) return value == s.faces[0];
  if (s.kind == 3u) return value == s.faces[0] || value == s.faces[1];
  if (s.kind == 0u) return value == s.key || value == s.faces[0] || value == s.faces[1];
  if ((value >> 8) != s.key) return false;
  int d = abs(int(value & 0xffu) - int(s.byte_value));
  if ((s.byte_window & 0x100u) != 0u) d = min(d, 256 - d);
  return d <= int(s.byte_window & 0xffu);
}

void main() {
  uint k = first_sample + gl_GlobalInvocationID.x;
  if (k >= sample_count) return;
  Sample s = samples[k];
  ivec2 size = textureSize(ids, 0);
  bool near_window =
      s.window.x > -2.0 && s.window.y > -2.0 && s.window.x < float(size.x + 2) && s.window.y < float(size.y + 2);
  bool visible = false;
  if (near_window) {
    ivec2 p = ivec2(floor(s.window));
    int r = s.kind == 3u ? 2 : 1;
    for (int dy = -r; dy <= r; ++dy)
      for (int dx = -r; dx <= r; ++dx) {
        ivec2 q = p + ivec2(dx, dy);
        if (all(greaterThanEqual(q, ivec2(0))) && all(lessThan(q, size))) {
          uvec2 halves = texelFetch(ids, q, 0).xy;
          visible = visible || holds(halves.x << 16 | halves.y, s);
        }
      }
  }
  flags[k] = visible ? 1u : 0u;
}
