#include "gpu/pencil/contour_blocks.hpp"

namespace plumbago::gpu {

namespace {
int blocks(int pixels) { return (pixels + kContourBlock - 1) / kContourBlock; }
}  // namespace

std::string contour_block_define() { return "#define CONTOUR_BLOCK " + std::to_string(kContourBlock) + "\n"; }

void fit_to_blocks(Texture& t, int width, int height) {
  if (t.width != blocks(width) || t.height != blocks(height)) t = make_texture(blocks(width), blocks(height), GL_R32F);
}

Texture make_contour_block_marks(int width, int height) {
  Texture t;
  fit_to_blocks(t, width, height);
  return t;
}

}  // namespace plumbago::gpu
