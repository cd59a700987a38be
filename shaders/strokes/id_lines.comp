#version 450 core
// The ID image's lines: the steps of gpu/strokes/id_lines.cpp before the draw.
//   STEP_COUNT: per entry, its quads (strokes/id_lines.glsl quads_of);
//   STEP_ARGS:  one invocation, after their prefix sums: the draws of a point a quad, one of the
//               creases' and borders' (the entries before silhouette_entry), one of the rest.
// The table's header (strokes/window_paths.glsl) holds the counts and the dispatch.
#if defined(STEP_ARGS)
layout(local_size_x = 1) in;
#else
layout(local_size_x = 64) in;  // kRowsGroup
#endif

#include "strokes/id_lines.glsl"
#include "util/rows.glsl"

uniform uint commands_at;  // where the draws' commands go in pieces[]

void main() {
#if defined(STEP_COUNT)
  uint e = row_index();
  if (e >= entry_count) return;
  Path p = paths[path_of_entry(e)];
  double t0, t1;
  pieces[e] = quads_of(p, e - p.first_entry, t0, t1);
#elif defined(STEP_ARGS)
  uint at = commands_at, lines = pieces[silhouette_entry];  // DrawArraysIndirectCommand: count, 1, first, 0
  pieces[at] = lines, pieces[at + 1u] = 1u, pieces[at + 2u] = 0u, pieces[at + 3u] = 0u;
  pieces[at + 4u] = pieces[entry_count] - lines, pieces[at + 5u] = 1u, pieces[at + 6u] = lines, pieces[at + 7u] = 0u;
#endif
}
