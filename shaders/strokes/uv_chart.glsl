// A mesh's (u, v) chart as a point-location table on the GPU, in double: the twin of
// common/strokes/uv_chart.cpp UvChart (gpu/strokes/decal_rows.cpp uploads it once). Its buffers
// take bindings 0, 3 and 6.
struct Chart {     // gpu/strokes/decal_rows.cpp ChartRow
  dvec2 lo, hi;    // the chart's box
  uint cells;      // its grid's cells a side
  uint periodic;   // 1: u's period is 1
  uint object;     // the object its mesh is
  uint first_face; // its face 0's row in ChartFaces
  uint first_start, pad0, pad1, pad2;  // its cells' starts in Buckets
};
struct ChartFace {  // gpu/strokes/decal_rows.cpp ChartFaceRow: a face's corners' (u, v) and positions
  vec2 uv0, uv1, uv2;
  vec4 p0, p1, p2;
};
layout(std430, binding = 0) readonly buffer Charts { Chart charts[]; };
// Per chart, its cells' starts (cells^2 + 1, indices into this buffer), then the faces listed.
layout(std430, binding = 3) readonly buffer Buckets { uint buckets[]; };
layout(std430, binding = 6) readonly buffer ChartFaces { ChartFace chart_faces[]; };

struct UvHit {
  uint face;
  dvec3 bary;
};

ivec2 chart_cell(Chart ch, dvec2 uv) {
  dvec2 t = (uv - ch.lo) / max(ch.hi - ch.lo, dvec2(1e-300lf)) * double(ch.cells);
  return clamp(ivec2(floor(t)), ivec2(0), ivec2(int(ch.cells) - 1));
}

// UvChart::locate_in_chart: the face of uv's cell it lies deepest in (the last of equals).
bool locate_in_chart(Chart ch, dvec2 uv, out UvHit hit) {
  if (uv.x < ch.lo.x || uv.y < ch.lo.y || uv.x > ch.hi.x || uv.y > ch.hi.y) return false;
  ivec2 c = chart_cell(ch, uv);
  uint bucket = ch.first_start + uint(c.y) * ch.cells + uint(c.x);
  double deepest = -1e-9lf;
  bool found = false;
  for (uint i = buckets[bucket]; i < buckets[bucket + 1u]; ++i) {
    uint f = buckets[i];
    ChartFace t = chart_faces[ch.first_face + f];
    precise dvec2 a = dvec2(t.uv0), e1 = dvec2(t.uv1) - a, e2 = dvec2(t.uv2) - a, d = uv - a;
    precise double det = e1.x * e2.y - e1.y * e2.x;
    if (det == 0.0lf) continue;
    precise double b1 = (d.x * e2.y - d.y * e2.x) / det, b2 = (e1.x * d.y - e1.y * d.x) / det;
    precise double depth = min(min(1.0lf - b1 - b2, b1), b2);
    if (depth >= deepest) deepest = depth, found = true, hit = UvHit(f, dvec3(1.0lf - b1 - b2, b1, b2));
  }
  return found;
}

// UvChart::locate: on a periodic chart u is taken modulo 1 first, then 1 further.
bool locate(Chart ch, dvec2 uv, out UvHit hit) {
  if (ch.periodic != 0u) uv.x = ch.lo.x + (uv.x - ch.lo.x - floor(uv.x - ch.lo.x));
  return locate_in_chart(ch, uv, hit) || (ch.periodic != 0u && locate_in_chart(ch, dvec2(uv.x + 1.0lf, uv.y), hit));
}

// UvChart::position: the hit's point of the mesh, in its object's space.
dvec3 position(Chart ch, UvHit hit) {
  ChartFace t = chart_faces[ch.first_face + hit.face];
  precise dvec3 p = hit.bary.x * dvec3(t.p0.xyz) + hit.bary.y * dvec3(t.p1.xyz) + hit.bary.z * dvec3(t.p2.xyz);
  return p;
}
