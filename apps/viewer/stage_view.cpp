#include "apps/viewer/stage_view.hpp"

#include <sstream>
#include <stdexcept>

#include "common/util/visualize.hpp"

namespace plumbago {
namespace {

// A gray image as RGB; more channels as they are (the window shows the first three).
Image gray_as_rgb(Image img) {
  if (img.channels != 1) return img;
  Image out(img.width, img.height, 3);
  for (size_t i = 0; i < img.pixels(); ++i)
    for (size_t c = 0; c < 3; ++c) out.data[i * 3 + c] = img.data[i];
  return out;
}

}  // namespace

const Image& StageView::selected(const Frame& frame) const {
  auto it = frame.buffers.find(buffer_);
  if (it != frame.buffers.end()) return it->second;
  std::ostringstream known;
  for (const auto& [name, img] : frame.buffers) known << (known.tellp() > 0 ? ", " : "") << name;
  throw std::invalid_argument("no buffer '" + buffer_ + "' in this frame (it has: " + known.str() + ")");
}

Image StageView::image(const Frame& frame) const {
  return buffer_.empty() ? frame.color : gray_as_rgb(viewable(buffer_, selected(frame)));
}

std::string StageView::readout(const Frame& frame, glm::ivec2 pixel) const {
  const Image& img = buffer_.empty() ? frame.color : selected(frame);
  if (pixel.x < 0 || pixel.y < 0 || pixel.x >= img.width || pixel.y >= img.height) return "";
  std::ostringstream s;
  s << (buffer_.empty() ? "color" : buffer_) << " at (" << pixel.x << ", " << pixel.y << "):";
  for (int c = 0; c < img.channels; ++c) s << ' ' << img.at(pixel.x, pixel.y, c);
  return s.str();
}

}  // namespace plumbago
