#version 450 core
// The ID image's lines: the steps of gpu/strokes/id_lines.cpp before the draw.
//   STEP_COUNT: per entry, its quads (strokes/id_lines.glsl quads_of);
//   STEP_ARGS:  one invocation, after their prefix sums: the draws of a point a quad, one of the
//               creases' and borders' (the entries before silhouette_entry), one of the rest.
#if defined(STEP_ARGS)
layout(local_size_x = 1) in;
#else
layout(local_size_x = 64) in;  // gpu/gl/program.hpp dispatch_in_chunks
#endif

#include "strokes/id_lines.glsl"

uniform uint first;             // of this dispatch
uniform uint silhouette_entry;  // the first entry of the first silhouette path (entry_count: none)

void main() {
#if defined(STEP_COUNT)
  uint e = first + gl_GlobalInvocationID.x;
  if (e >= entry_count) return;
  Path p = paths[path_of_entry(e, path_count)];
  double t0, t1;
  pieces[e] = quads_of(p, e - p.first_entry, t0, t1);
#elif defined(STEP_ARGS)
  uint at = entry_count + 1u, lines = pieces[silhouette_entry];  // DrawArraysIndirectCommand: count, 1, first, 0
  pieces[at] = lines, pieces[at + 1u] = 1u, pieces[at + 2u] = 0u, pieces[at + 3u] = 0u;
  pieces[at + 4u] = pieces[entry_count] - lines, pieces[at + 5u] = 1u, pieces[at + 6u] = lines, pieces[at + 7u] = 0u;
#endif
}
