// The ID image's lines on the GPU (Kalnins et al. 2002, §4.6; common/strokes/id_image.hpp rules
// 2 and 3), drawn from the frame's path table (gpu/strokes/window_paths.hpp): each entry's
// quads counted (shaders/strokes/id_lines.comp), placed by a prefix sum, then drawn by an
// indirect draw of a point a quad a rule (the creases and borders, then the silhouettes, whose
// entries follow theirs), which the geometry shader (shaders/strokes/id_lines.geom) expands
// into the reference's two triangles, in path order as the reference draws them
// (common/strokes/id_image.cpp id_line_triangles). Nothing is read back.
#pragma once

#include "common/strokes/id_image.hpp"
#include "common/strokes/strokes.hpp"
#include "gpu/gl/gl_objects.hpp"
#include "gpu/gl/program.hpp"
#include "gpu/gl/scan.hpp"
#include "gpu/strokes/window_paths.hpp"

namespace plumbago::gpu {

class IdLines {
 public:
  IdLines();
  // Counts and places the quads of the lines of `table` in a window of `width` x `height`.
  void prepare(const UploadedPaths& table, const StrokesParams& p, int width, int height, float near);
  // Draws the quads `table` prepared of one rule into the bound framebuffer, with the depth
  // test as set.
  void draw(const UploadedPaths& table, IdLineRule rule);

 private:
  void bind(const UploadedPaths& table) const;

  Program count_, args_, draw_;
  ExclusiveScan scan_;
  Buffer pieces_;
  size_t capacity_ = 0, commands_ = 0;  // commands_: where the two draws' commands start (uints)
  VertexArray empty_;
};

}  // namespace plumbago::gpu
