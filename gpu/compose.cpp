#include "gpu/compose.hpp"

namespace plumbago::gpu {

ComposePass::ComposePass() : program_("fullscreen.vert", "compose.frag", glsl_params<ComposeParams>()) {}

void ComposePass::run(const Texture& contour_darkness, const ComposeParams& p, Texture& out) {
  program_.set_params(p);
  pass_.draw(program_, {&contour_darkness}, out);
}

}  // namespace plumbago::gpu
