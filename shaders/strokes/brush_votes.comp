#version 450 core
// Coherent silhouettes' votes on the GPU (Kalnins et al. 2003): step 2. of
// common/strokes/coherent_silhouettes.hpp, in double as the reference makes them, one
// invocation per brush sample of the last frame (the first `total` of `slots`; the CPU clears
// the slots to no vote first): its world point projected with this frame's camera votes for the
// nearest point, within search_px, of a visible silhouette run of this frame (the runs'
// window polylines as strokes/run_walk.glsl walks them, the pieces' depths linear between
// their ends) whose depth agrees within depth_tolerance of its own; the nearest, among
// equals the first in run and piece order, as the reference takes it. As the reference's
// PieceGrid, the pieces lie on a grid of square cells, one program per step:
//   STEP_PIECES: per run listed, its pieces, and a count in each cell a short piece's box
//                touches (at most 2 x 2: a piece no larger than a cell); a longer one is
//                listed apart;
//   (gpu/gl/scan.hpp: the cells' counts made the entries' starts)
//   STEP_BIN:    per piece, its index in each of its cells' entries (a cell's start becomes
//                the next cell's as it fills);
//   STEP_VOTE:   per sample, the pieces of the cells its search box touches, and the long ones.
// Each step is dispatched over what the GPU counted (gpu/gl/groups.hpp), not over the bounds.
layout(local_size_x = 64) in;

#define PATHS_BINDING 0
#define POINTS_BINDING 1
#include "strokes/window_paths.glsl"
#include "strokes/run_walk.glsl"
#include "util/lerp.glsl"

struct Sample {  // gpu/strokes/brush_votes.cpp SampleRecord
  double x, y, z, t;
  uint stroke, path;
};
struct Vote {  // gpu/strokes/brush_votes.cpp VoteRecord; run kNoVote: none
  double s, t;
  uint run, stroke, path, pad;
};
struct Frame {  // world to clip, to view; the window; the search; the grid's cell
  dmat4 clip, view;
  double width, height, search_px, depth_tolerance, cell;
  uint columns, rows;
};
struct Piece {  // of run `run`, the j-th along it: window ends, their depths and arc lengths
  dvec2 a, b;
  double da, db, sa, sb;
  uint run, j;
};

layout(std430, binding = 2) readonly buffer RunRows { Run run_rows[]; };
layout(std430, binding = 3) readonly buffer Listed { uint listed[]; };  // the runs listed, at listed_at
layout(std430, binding = 4) readonly buffer Samples { Sample samples[]; };
layout(std430, binding = 5) writeonly buffer Votes { Vote votes[]; };
layout(std430, binding = 6) readonly buffer FrameBlock { Frame f; };
layout(std430, binding = 7) readonly buffer Total { uint total; };  // the samples (brush_samples.comp)
layout(std430, binding = 8) buffer Pieces { Piece pieces[]; };
layout(std430, binding = 9) buffer Counts { uint piece_count, long_count; };  // zero before STEP_PIECES
layout(std430, binding = 10) buffer Cells { uint cells[]; };  // counts; then starts; then ends
layout(std430, binding = 11) buffer Entries { uint entries[]; };  // the cells' pieces, in cell order
layout(std430, binding = 12) buffer Longs { uint longs[]; };  // the pieces larger than a cell

uniform uint slots, listed_at, piece_capacity;

const uint kNoVote = 0xffffffffu, kSilhouette = 1u;  // SampleKind

// common/util/segment_grid.hpp SegmentGrid: the cells (x0, y0, x1, y1) of the box [lo, hi];
// what lies outside the window is in the border cells.
int cell_index(double v, uint n) { return clamp(int(floor(clamp(v / f.cell, -1e9lf, 1e9lf))), 0, int(n) - 1); }
ivec4 cells_of(dvec2 lo, dvec2 hi) {
  return ivec4(cell_index(lo.x, f.columns), cell_index(lo.y, f.rows), cell_index(hi.x, f.columns),
               cell_index(hi.y, f.rows));
}
uint cell_at(int x, int y) { return uint(y) * f.columns + uint(x); }
bool is_short(ivec4 c) { return c.z - c.x <= 1 && c.w - c.y <= 1; }
ivec4 piece_cells(Piece p) { return cells_of(min(p.a, p.b), max(p.a, p.b)); }

#ifdef STEP_PIECES
// The pieces of run r's window polyline: its points less one.
uint piece_total(uint r, Path p) {
  RunWalk w = start_run_walk(run_rows[r], p);
  RunPoint a;
  uint n = 0u;
  while (next_run_point(w, a)) ++n;
  return n > 0u ? n - 1u : 0u;
}

void add_piece(uint at, Piece piece) {
  pieces[at] = piece;
  ivec4 c = piece_cells(piece);
  if (!is_short(c)) {
    longs[atomicAdd(long_count, 1u)] = at;
    return;
  }
  for (int y = c.y; y <= c.w; ++y)
    for (int x = c.x; x <= c.z; ++x) atomicAdd(cells[cell_at(x, y)], 1u);
}

void main() {
  for (uint r = gl_GlobalInvocationID.x; r < listed[listed_at]; r += gl_NumWorkGroups.x * 64u) {
    Path p = paths[run_rows[r].path];
    if ((p.kind & 15u) != kSilhouette) continue;
    uint n = piece_total(r, p), at = n > 0u ? atomicAdd(piece_count, n) : 0u;
    if (n == 0u || at + n > piece_capacity) continue;  // past the CPU's bound: no votes (STEP_VOTE)
    RunWalk w = start_run_walk(run_rows[r], p);
    RunPoint a, b;
    next_run_point(w, a);
    double s = 0.0lf;
    for (uint j = 0u; next_run_point(w, b); a = b, ++j) {
      double next_s = s + distance(a.window, b.window);
      add_piece(at + j, Piece(a.window, b.window, a.depth, b.depth, s, next_s, r, j));
      s = next_s;
    }
  }
}
#endif

#ifdef STEP_BIN
void main() {
  if (piece_count > piece_capacity) return;
  for (uint i = gl_GlobalInvocationID.x; i < piece_count; i += gl_NumWorkGroups.x * 64u) {
    ivec4 c = piece_cells(pieces[i]);
    if (!is_short(c)) continue;
    for (int y = c.y; y <= c.w; ++y)
      for (int x = c.x; x <= c.z; ++x) entries[atomicAdd(cells[cell_at(x, y)], 1u)] = i;
  }
}
#endif

#ifdef STEP_VOTE
// The window position and linear depth of a world point (common/strokes/strokes.hpp
// WindowProjection).
dvec3 project(dvec3 world) {
  dvec4 c = f.clip * dvec4(world, 1.0lf);
  double d = -(f.view * dvec4(world, 1.0lf)).z;
  return dvec3((c.x / c.w * 0.5lf + 0.5lf) * f.width, (c.y / c.w * 0.5lf + 0.5lf) * f.height, d);
}

// common/util/segment_grid.hpp nearest_on: the share along a -> b of its point nearest q.
double nearest_share(dvec2 a, dvec2 b, dvec2 q) {
  dvec2 d = b - a;
  double len2 = dot(d, d);
  return len2 > 0.0lf ? clamp(dot(q - a, d) / len2, 0.0lf, 1.0lf) : 0.0lf;
}

struct Best {
  double distance;
  uint run, j;  // the piece's: among equals, the first in run and piece order
  double s;
};

// Piece i's vote of a point seen at q (window, depth), if nearer than the best so far.
void vote_on_piece(uint i, dvec3 q, inout Best best) {
  Piece p = pieces[i];
  double t = nearest_share(p.a, p.b, q.xy);
  double d = distance(p.a + t * (p.b - p.a), q.xy);
  bool nearer = d < best.distance || (d == best.distance && (p.run < best.run || (p.run == best.run && p.j < best.j)));
  if (nearer && abs(lerp(p.da, p.db, t) - q.z) <= f.depth_tolerance * q.z)
    best = Best(d, p.run, p.j, lerp(p.sa, p.sb, t));
}

// The best vote of a point seen at q: the pieces of the cells its search box touches (a margin of
// 1e-6 px keeps the box's rounding from losing a piece at exactly search_px), then the long ones.
void nearest(dvec3 q, inout Best best) {
  double grow = f.search_px + 1e-6lf;
  ivec4 c = cells_of(q.xy - grow, q.xy + grow);
  for (int y = c.y; y <= c.w; ++y)
    for (int x = c.x; x <= c.z; ++x) {
      uint cell = cell_at(x, y);
      for (uint e = cell == 0u ? 0u : cells[cell - 1u]; e < cells[cell]; ++e) vote_on_piece(entries[e], q, best);
    }
  for (uint e = 0u; e < long_count; ++e) vote_on_piece(longs[e], q, best);
}

void main() {
  for (uint i = gl_GlobalInvocationID.x; i < min(total, slots); i += gl_NumWorkGroups.x * 64u) {
    Sample x = samples[i];
    dvec3 q = project(dvec3(x.x, x.y, x.z));
    Best best = Best(f.search_px, kNoVote, kNoVote, 0.0lf);
    if (q.z > 0.0lf && piece_count <= piece_capacity) nearest(q, best);
    votes[i] = Vote(best.s, x.t, best.run, x.stroke, x.path, 0u);
  }
}
#endif
