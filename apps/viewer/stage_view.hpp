// Stage view: one intermediate buffer of the current frame (the GPU renderer's kept
// buffers, the names `render --dump-stages` writes) shown in place of the final image,
// as --dump-stages's PNG shows it (common/util/visualize.hpp), with the raw values under the
// cursor.
#pragma once

#include <glm/glm.hpp>
#include <string>

#include "common/core/frame.hpp"

namespace plumbago {

class StageView {
 public:
  const std::string& buffer() const { return buffer_; }  // "" = the final image
  void select(std::string buffer) { buffer_ = std::move(buffer); }
  // What the frame area shows of `frame`, RGB; throws std::invalid_argument naming the
  // frame's buffers when the selected one is not among them.
  Image image(const Frame& frame) const;
  // The selected buffer's raw values at `pixel` (row 0 at the bottom), "" outside it.
  std::string readout(const Frame& frame, glm::ivec2 pixel) const;

 private:
  const Image& selected(const Frame& frame) const;
  std::string buffer_;
};

}  // namespace plumbago
